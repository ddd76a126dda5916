#include "StateEditor.h"

#include <QMap>

namespace DriveDesk {

QList<WriteStep> StateEditor::restoringSteps(quint8 setMask, const Values &before)
{
    QMap<qint32, quint8> masks; // earlier value -> its sets, in a stable order
    for (int set = 0; set < kParameterSets; ++set) {
        const std::optional<qint32> value = before[std::size_t(set)];
        if ((setMask & (1u << set)) && value)
            masks[*value] |= quint8(1u << set);
    }
    QList<WriteStep> steps;
    for (auto it = masks.cbegin(); it != masks.cend(); ++it)
        steps << WriteStep { it.value(), it.key(), false };
    return steps;
}

} // namespace DriveDesk
