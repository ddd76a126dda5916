#include "ExportFeature.h"

#include "frame/FileProblem.h"

#include "model/ParameterModel.h"
#include "parameters/ParameterCsv.h"

#include <QAction>
#include <QDate>
#include <QDir>
#include <QMenu>

namespace DriveDesk {

ExportFeature::ExportFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_action = new QAction(tr("Export as &CSV..."), this);
    m_action->setObjectName(QStringLiteral("exportCsvAction"));
    m_action->setToolTip(tr("Write every parameter with its unit and each set's value as shown "
                            "to a CSV file for a spreadsheet"));
    connect(m_action, &QAction::triggered, this, [this] {
        const QString name
            = QStringLiteral("parameters-%1.csv").arg(QDate::currentDate().toString(Qt::ISODate));
        this->frame().chooseFileToWrite(tr("Export as CSV"), name, tr("CSV files (*.csv)"),
                                        [this](const QString &path) { return exportCsv(path); });
    });
    QMenu *file = frame.menu(WindowFrame::Menu::File);
    file->addSeparator();
    file->addAction(m_action);
}

void ExportFeature::updateActions()
{
    m_action->setEnabled(frame().model()->rowCount() > 0); // groups shown
}

bool ExportFeature::exportCsv(const QString &path)
{
    const DriveDescription shown = frame().state()->description();
    QString error;
    // As the user's spreadsheet reads it: a German one wants ';' between decimal commas.
    if (!saveParametersAsCsv(path, shown, &error, CsvStyle::forSpreadsheet())) {
        const QString text = tr("Not exported: %1. The file on disk is as it was.").arg(error);
        frame().showMessage(text);
        showFileProblem(frame().frameWidget(), tr("Export as CSV"), text);
        return false;
    }
    frame().showMessage(tr("Exported %n parameter(s) to %1.", nullptr, shown.parameterCount())
                            .arg(QDir::toNativeSeparators(path)));
    return true;
}

} // namespace DriveDesk
