#pragma once

#include "parameters/DriveDescription.h"
#include "scope/ScopeChannel.h"
#include "session/ScopeAssignment.h"

#include <QColor>
#include <QWidget>

#include <array>

class QCheckBox;
class QComboBox;
class QLabel;
class QToolButton;

namespace DriveDesk {

// The four channels of the scope, a row each: shown or not, its colour, its source (on a drive
// with channel assignment, any parameter the drive permits as process data), its own value
// axis or the shared one, and its unit. It says what the user chose; the dock acts on it.
class ScopeChannelPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ScopeChannelPanel(QWidget *parent = nullptr);

    // The drive whose parameters can be chosen; nullptr: none (a recording from a file).
    void setDrive(const DriveDescription *drive);
    // What the recording shows on each channel now (after the assignment was read back).
    void setChannels(const ScopeChannels &channels);
    // The sources chosen: an entry for each channel whose source the user picked; empty
    // entries stay as the drive has them. Sources set before the drive is known are chosen
    // once a drive offers them.
    ScopeAssignment choices() const;
    void setChoices(const ScopeAssignment &choices);
    // What the user asked for, offered by this drive or not: what is remembered.
    ScopeAssignment wantedChoices() const { return m_wanted; }
    // While recording, the sources cannot change.
    void setSourcesEditable(bool editable);

    bool isChannelVisible(int channel) const;
    void setChannelVisible(int channel, bool visible);
    QColor channelColor(int channel) const { return m_colors[std::size_t(channel)]; }
    void setChannelColor(int channel, const QColor &color);
    bool hasOwnAxis(int channel) const;
    void setOwnAxis(int channel, bool own);

signals:
    void choicesChanged();
    void visibilityChanged(int channel, bool visible);
    void colorChanged(int channel, const QColor &color);
    void ownAxisChanged(int channel, bool own);

private:
    // The id typed into channel's source field and confirmed with Enter.
    void chooseTyped(int channel);

    struct Row
    {
        QToolButton *color = nullptr;
        QCheckBox *visible = nullptr;
        QComboBox *source = nullptr;
        QComboBox *set = nullptr; // for a set-programmable source
        QCheckBox *ownAxis = nullptr;
        QLabel *unit = nullptr;
    };

    void fillSources(int channel);
    void chooseColor(int channel);
    void paintSwatch(int channel);
    void noteNarrowRange(int channel);
    void updateSet(int channel);
    const ParameterDescription *sourceOf(int channel) const;

    void applyWanted();

    const DriveDescription *m_drive = nullptr;
    // The sources asked for, kept while the drive offers none of them (no drive yet).
    ScopeAssignment m_wanted;
    std::array<Row, 4> m_rows{};
    std::array<QColor, 4> m_colors{};
    bool m_filling = false;
};

} // namespace DriveDesk
