#pragma once

#include "session/DownloadPlan.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// How a download went, parameter by parameter: what the drive holds now as the file says
// (read back), what it refused and why, what the plan left and why, what was never sent
// because the download stopped first, and what was sent but never answered. Each set of each
// value to write is on exactly one line, and every line is true of the drive.
struct DownloadReport
{
    Q_DECLARE_TR_FUNCTIONS(DownloadReport)
public:
    struct Line
    {
        QString id;
        QString name;
        QString detail; // the sets and value written, or the reason
        quint8 sets = 0; // the sets the line is about (set 0 for a value not per set)
    };

    QList<Line> written;    // acknowledged and read back as the file holds it
    QList<Line> refused;    // refused by the drive (it holds what it held), or read back other
    QList<Line> skipped;
    QList<Line> notWritten; // never sent: the drive holds what it held
    // Sent, and no answer came (or acknowledged, and the read-back got none): the drive may
    // hold the file's value or its own.
    QList<Line> unknown;
    int writtenValues = 0;
    int unchanged = 0;
    int readOnlyDiffering = 0;
    QString stopReason; // why the download stopped early; empty when it went through

    // Everything to write was written and read back as the file holds it.
    bool isComplete() const
    {
        return refused.isEmpty() && notWritten.isEmpty() && unknown.isEmpty()
            && stopReason.isEmpty();
    }
    // The report for a user: a summary line, then each list.
    QString text() const;
};

// outcomes[i] is what became of plan.items[i], empty where it was never sent; `drive` gives
// the parameters' formats.
DownloadReport reportDownload(const DownloadPlan &plan,
                              const QList<std::optional<WriteOutcome>> &outcomes,
                              const QString &stopReason, const DriveDescription &drive);

} // namespace DriveDesk
