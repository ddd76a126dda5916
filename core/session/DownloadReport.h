#pragma once

#include "session/DownloadPlan.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// How a download went, parameter by parameter: what the drive holds now as the file says
// (read back), what it refused and why, what the plan left and why, and what was never sent
// because the download stopped first.
struct DownloadReport
{
    Q_DECLARE_TR_FUNCTIONS(DownloadReport)
public:
    struct Line
    {
        QString id;
        QString name;
        QString detail; // the sets and value written, or the reason
    };

    QList<Line> written;
    QList<Line> refused;    // refused, unanswered, or read back other than written
    QList<Line> skipped;
    QList<Line> notWritten; // never sent
    int writtenValues = 0;
    int unchanged = 0;
    int readOnlyDiffering = 0;
    QString stopReason; // why the download stopped early; empty when it went through

    // Everything to write was written and read back as the file holds it.
    bool isComplete() const
    {
        return refused.isEmpty() && notWritten.isEmpty() && stopReason.isEmpty();
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
