#pragma once

#include "state/EditOutcome.h"

#include <functional>

namespace DriveDesk {

class DriveState;

// One way to change a parameter's values, for a drive and for a parameter file opened to edit:
// ValueEdits writes to a drive through its per-parameter queue with read-back, FileEdits
// changes the file's values in memory. Either applies the set-0 rule, shows what it did in its
// DriveState and ends each change in one EditOutcome, which EditText says in words.
class StateEditor
{
public:
    using Done = std::function<void(const EditOutcome &)>;
    using Values = std::array<std::optional<qint32>, kParameterSets>;

    virtual ~StateEditor() = default;

    virtual DriveState *state() const = 0;
    // The steps in order (undo and redo give any); `reset`: each step puts the default.
    virtual void apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
                       Done done = {}) = 0;
    // Puts back what the sets of the mask held before a change (undo).
    virtual void restore(const ParameterDescription &parameter, quint8 setMask,
                         const Values &before, Done done = {}) = 0;

    // `raw` into the sets of the mask.
    void write(const ParameterDescription &parameter, quint8 setMask, qint32 raw, Done done = {})
    {
        apply(parameter, { WriteStep { setMask, raw, false } }, false, std::move(done));
    }
    void resetToDefault(const ParameterDescription &parameter, quint8 setMask, Done done = {})
    {
        apply(parameter, { WriteStep { setMask, 0, true } }, true, std::move(done));
    }

    // The writes that put earlier values back: one per distinct value, the sets whose earlier
    // value is unknown left out.
    static QList<WriteStep> restoringSteps(quint8 setMask, const Values &before);
};

} // namespace DriveDesk
