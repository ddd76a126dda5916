#pragma once

#include "state/StateEditor.h"

namespace DriveDesk {

// The edits of a parameter file opened to edit: each change goes into the file's DriveState at
// once, and its outcome says so (every set asked for holds the value, as if read back). Nothing
// reaches a drive. The state outlives it.
class FileEdits : public StateEditor
{
public:
    explicit FileEdits(DriveState *state);

    DriveState *state() const override { return m_state; }
    void apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
               Done done = {}) override;
    // Exactly the values before, a value never read included.
    void restore(const ParameterDescription &parameter, quint8 setMask, const Values &before,
                 Done done = {}) override;

private:
    DriveState *m_state = nullptr;
};

} // namespace DriveDesk
