#include "DownloadReport.h"

#include "parameters/ParameterFormat.h"
#include "parameters/SetList.h"

#include <bit>
#include <map>

namespace DriveDesk {

namespace {

// "sets 0-3: 3000 1/min; set 4: 2000 1/min", or the one value of a parameter not per set.
QString valuesText(const DownloadItem &item, quint8 mask,
                   const std::array<std::optional<qint32>, kParameterSets> &values,
                   const ParameterFormat &format)
{
    if (!item.change.setProgrammable)
        return values[0] ? format.text(*values[0]) : QString();
    std::map<qint32, quint8> sets;
    for (int set = 0; set < kParameterSets; ++set) {
        if ((mask & (1u << set)) && values[std::size_t(set)])
            sets[*values[std::size_t(set)]] |= quint8(1u << set);
    }
    QStringList parts;
    for (const auto &[value, setMask] : sets)
        parts << QStringLiteral("%1: %2").arg(SetList::text(setMask), format.text(value));
    return parts.join(QStringLiteral("; "));
}

QString setsText(const DownloadItem &item, quint8 mask)
{
    return item.change.setProgrammable ? SetList::text(mask) : DownloadReport::tr("the value");
}

void appendSection(QString &text, const QString &title, const QList<DownloadReport::Line> &lines)
{
    if (lines.isEmpty())
        return;
    text += title + QLatin1Char('\n');
    for (const DownloadReport::Line &line : lines)
        text += QStringLiteral("  %1  %2: %3\n").arg(line.id, line.name, line.detail);
}

} // namespace

DownloadReport reportDownload(const DownloadPlan &plan,
                              const QList<std::optional<WriteOutcome>> &outcomes,
                              const QString &stopReason, const DriveDescription &drive)
{
    DownloadReport report;
    report.unchanged = plan.unchanged;
    report.readOnlyDiffering = plan.readOnlyDiffering;
    report.stopReason = stopReason;
    for (const DownloadSkip &skip : plan.skipped)
        report.skipped << DownloadReport::Line{skip.id, skip.name, skip.reason};
    for (qsizetype i = 0; i < plan.items.size(); ++i) {
        const DownloadItem &item = plan.items.at(i);
        const ParameterDescription *parameter = drive.find(item.change.address);
        const ParameterFormat format(parameter ? *parameter : ParameterDescription{});
        const std::optional<WriteOutcome> outcome = outcomes.value(i);
        const auto line = [&item](const QString &detail) {
            return DownloadReport::Line{item.id, item.name, detail};
        };
        if (!outcome) {
            report.notWritten << line(stopReason.isEmpty()
                                          ? DownloadReport::tr("not sent")
                                          : DownloadReport::tr("not sent: %1").arg(stopReason));
            continue;
        }
        quint8 held = 0;
        quint8 notSent = 0;
        quint8 unread = 0;
        QStringList otherwise;
        for (int set = 0; set < kParameterSets; ++set) {
            const auto s = std::size_t(set);
            const auto bit = quint8(1u << set);
            if (!item.wanted[s] || (outcome->refusedMask & bit))
                continue;
            if (!(outcome->acknowledgedMask & bit)) {
                notSent |= bit;
                continue;
            }
            const std::optional<qint32> back = outcome->readBack[s];
            if (back == item.wanted[s]) {
                held |= bit;
            } else if (back) {
                otherwise << DownloadReport::tr("%1 holds %2")
                                 .arg(setsText(item, bit), format.text(*back));
            } else {
                unread |= bit;
            }
        }
        if (unread) {
            otherwise << DownloadReport::tr("%1 could not be read back (%2)")
                             .arg(setsText(item, unread), outcome->readBackError);
        }
        if (held) {
            report.written << line(valuesText(item, held, item.wanted, format));
            report.writtenValues += std::popcount(unsigned(held));
        }
        if (outcome->refusedMask && outcome->connectionFailed) {
            // The request may have reached the drive and only its answer got lost.
            report.refused << line(DownloadReport::tr("%1: no answer, so whether the drive took "
                                                      "the value is unknown (%2)")
                                       .arg(setsText(item, outcome->refusedMask), outcome->error));
        } else if (outcome->refusedMask) {
            report.refused << line(QStringLiteral("%1: %2").arg(
                setsText(item, outcome->refusedMask), outcome->error));
        }
        if (!otherwise.isEmpty()) {
            report.refused << line(DownloadReport::tr("written %1, but %2")
                                       .arg(valuesText(item, 0xFF, item.wanted, format),
                                            otherwise.join(QStringLiteral(", "))));
        }
        if (notSent) {
            report.notWritten << line(DownloadReport::tr("%1 not sent: %2")
                                          .arg(setsText(item, notSent),
                                               stopReason.isEmpty() ? outcome->error : stopReason));
        }
    }
    return report;
}

QString DownloadReport::text() const
{
    QString text = tr("%n value(s) written and read back", nullptr, writtenValues)
        + QStringLiteral(", ") + tr("%n unchanged", nullptr, unchanged) + QStringLiteral(", ")
        + tr("%n refused", nullptr, int(refused.size())) + QStringLiteral(", ")
        + tr("%n skipped", nullptr, int(skipped.size()));
    if (!notWritten.isEmpty())
        text += QStringLiteral(", ") + tr("%n not written", nullptr, int(notWritten.size()));
    text += QLatin1Char('\n');
    if (readOnlyDiffering) {
        text += tr("%n read-only value(s) of the file differ from the drive's; they are never "
                   "written", nullptr, readOnlyDiffering)
            + QLatin1Char('\n');
    }
    if (!stopReason.isEmpty())
        text += tr("The download stopped: %1").arg(stopReason) + QLatin1Char('\n');
    appendSection(text, tr("Written:"), written);
    appendSection(text, tr("Refused:"), refused);
    appendSection(text, tr("Skipped:"), skipped);
    appendSection(text, tr("Not written:"), notWritten);
    return text;
}

} // namespace DriveDesk
