#pragma once

#include "plant/PlantFile.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;

namespace DriveDesk {

// A link added to a plant: its name, where the line is, the protocol, the baud rate and a DIN
// bus's addresses; for a new plant also the machine's name. What may go into the plant file is
// PlantFile's rule: the dialog closes only on a plant that reads back, and otherwise shows
// the reader's reason (the place and what is wrong) below the form. Opened with open().
class PlantLinkDialog : public QDialog
{
    Q_OBJECT
public:
    // `newPlant`: the machine's name is asked for too, and `plant` is a start with no links.
    PlantLinkDialog(const Plant &plant, bool newPlant, QWidget *parent = nullptr);

    // The plant with the link added, as the form says.
    Plant plant() const;
    QLineEdit *machineEdit() const { return m_machine; }
    QLineEdit *nameEdit() const { return m_name; }
    QLineEdit *connectEdit() const { return m_connect; }
    QComboBox *protocolBox() const { return m_protocol; }
    QLineEdit *baudEdit() const { return m_baud; }
    QLineEdit *addressesEdit() const { return m_addresses; }
    QString problem() const;

public slots:
    void accept() override;

private:
    // Nothing, with the reason, for numbers that are not numbers.
    std::optional<Plant> read(QString *error) const;

    Plant m_plant;
    QLineEdit *m_machine = nullptr;
    QLineEdit *m_name = nullptr;
    QLineEdit *m_connect = nullptr;
    QComboBox *m_protocol = nullptr;
    QLineEdit *m_baud = nullptr;
    QLineEdit *m_addresses = nullptr;
    QLabel *m_problem = nullptr;
};

} // namespace DriveDesk
