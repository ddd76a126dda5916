#include "DownloadReport.h"

#include "parameters/ParameterFormat.h"
#include "parameters/SetList.h"

#include <algorithm>
#include <bit>
#include <map>
#include <vector>

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
    // In the order of the sets, as the table shows them: the lowest set of each value first.
    std::vector<std::pair<quint8, qint32>> bySet;
    for (const auto &[value, setMask] : sets)
        bySet.emplace_back(setMask, value);
    std::sort(bySet.begin(), bySet.end(), [](const auto &a, const auto &b) {
        return std::countr_zero(unsigned(a.first)) < std::countr_zero(unsigned(b.first));
    });
    QStringList parts;
    for (const auto &[setMask, value] : bySet)
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
        const auto line = [&item](const QString &detail, quint8 sets) {
            return DownloadReport::Line{item.id, item.name, detail, sets};
        };
        quint8 wanted = 0;
        for (int set = 0; set < kParameterSets; ++set) {
            if (item.wanted[std::size_t(set)])
                wanted |= quint8(1u << set);
        }
        if (!outcome) {
            report.notWritten << line(stopReason.isEmpty()
                                          ? DownloadReport::tr("not sent")
                                          : DownloadReport::tr("not sent: %1").arg(stopReason),
                                      wanted);
            continue;
        }
        // Each set on exactly one line: what the drive said about its write decides.
        quint8 held = 0;
        quint8 unread = 0;
        quint8 unanswered = 0;
        quint8 refused = 0;
        quint8 notSent = 0;
        std::map<qint32, quint8> other; // read back other than written
        std::map<qint32, quint8> notTaken; // no answer to the write, and read holding this
        for (int set = 0; set < kParameterSets; ++set) {
            const auto s = std::size_t(set);
            const auto bit = quint8(1u << set);
            if (!(wanted & bit))
                continue;
            if (outcome->acknowledgedMask & bit) {
                const std::optional<qint32> back = outcome->readBack[s];
                if (back == item.wanted[s])
                    held |= bit;
                else if (back)
                    other[*back] |= bit;
                else
                    unread |= bit;
            } else if (outcome->unansweredMask & bit) {
                unanswered |= bit;
            } else if ((outcome->refusedMask & bit) && !(outcome->notSentMask & bit)) {
                // A write without answer that reading the set settled: it holds another value.
                const std::optional<qint32> back = outcome->readBack[s];
                if (back && back != item.wanted[s])
                    notTaken[*back] |= bit;
                else
                    refused |= bit;
            } else {
                notSent |= bit;
            }
        }
        if (held) {
            report.written << line(valuesText(item, held, item.wanted, format), held);
            report.writtenValues += std::popcount(unsigned(held));
        }
        if (refused) {
            report.refused << line(QStringLiteral("%1: %2").arg(setsText(item, refused),
                                                               outcome->error),
                                   refused);
        }
        for (const auto &[value, sets] : other) {
            report.refused << line(DownloadReport::tr("written %1, but %2 holds %3")
                                       .arg(valuesText(item, sets, item.wanted, format),
                                            setsText(item, sets), format.text(value)),
                                   sets);
        }
        for (const auto &[value, sets] : notTaken) {
            report.refused << line(DownloadReport::tr("%1: no answer to writing %2, and the "
                                                      "drive holds %3: not written")
                                       .arg(setsText(item, sets),
                                            valuesText(item, sets, item.wanted, format),
                                            format.text(value)),
                                   sets);
        }
        if (unanswered) {
            // The request may have reached the drive and only its answer got lost.
            report.unknown << line(DownloadReport::tr("%1: no answer, so whether the drive "
                                                      "took %2 is unknown (%3)")
                                       .arg(setsText(item, unanswered),
                                            valuesText(item, unanswered, item.wanted, format),
                                            outcome->error),
                                   unanswered);
        }
        if (unread) {
            report.unknown << line(DownloadReport::tr("%1: the drive acknowledged %2, but it "
                                                      "could not be read back (%3)")
                                       .arg(setsText(item, unread),
                                            valuesText(item, unread, item.wanted, format),
                                            outcome->readBackError),
                                   unread);
        }
        if (notSent) {
            report.notWritten << line(DownloadReport::tr("%1 not sent: %2")
                                          .arg(setsText(item, notSent),
                                               stopReason.isEmpty() ? outcome->error : stopReason),
                                      notSent);
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
    if (!unknown.isEmpty())
        text += QStringLiteral(", ") + tr("%n unknown", nullptr, int(unknown.size()));
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
    appendSection(text, tr("Unknown (sent, no answer):"), unknown);
    return text;
}

} // namespace DriveDesk
