#pragma once

#include "session/DownloadPlan.h"
#include "session/DownloadReport.h"

#include <QHash>
#include <QStringList>

#include <algorithm>

// Whether a download report is true of the drive, read again after the download: shared by the
// tests of one drive's download and of a plant's.
namespace DriveDesk::DownloadCheck {

// The sets of `item` the download is to write.
inline quint8 wantedSets(const DownloadItem &item)
{
    quint8 sets = 0;
    for (int set = 0; set < kParameterSets; ++set) {
        if (item.wanted[std::size_t(set)])
            sets |= quint8(1u << set);
    }
    return sets;
}

// Every set of every value to write is on exactly one line of the report, and each line is
// true of `after` (the drive read again): written -> the file's value, refused or not
// written -> what the drive held before, unknown -> either. Empty when it all holds.
inline QString untrueLines(const DownloadPlan &plan, const DownloadReport &report,
                           const DriveDescription &after)
{
    enum class Says : quint8 { New, Old, Either };
    QStringList wrong;
    QHash<QString, quint8> covered;
    const auto check = [&](const QList<DownloadReport::Line> &lines, Says says) {
        for (const DownloadReport::Line &line : lines) {
            const auto item
                = std::find_if(plan.items.begin(), plan.items.end(),
                               [&line](const DownloadItem &i) { return i.id == line.id; });
            if (item == plan.items.end()) {
                wrong << QStringLiteral("%1: no such item").arg(line.id);
                continue;
            }
            if (covered.value(line.id) & line.sets)
                wrong << QStringLiteral("%1: sets %2 on two lines")
                             .arg(line.id)
                             .arg(line.sets, 0, 16);
            covered[line.id] |= line.sets;
            const ParameterDescription *p = after.find(item->change.address);
            for (int set = 0; set < kParameterSets; ++set) {
                const auto s = std::size_t(set);
                if (!(line.sets & (1u << set)) || !p)
                    continue;
                const std::optional<qint32> now = p->values[s];
                const bool isNew = now == item->wanted[s];
                const bool isOld = !item->before[s] || now == item->before[s];
                if ((says == Says::New && !isNew) || (says == Says::Old && !isOld)
                    || (says == Says::Either && !isNew && !isOld)) {
                    wrong << QStringLiteral("%1 set %2: drive holds %3 but the report says \"%4\"")
                                 .arg(line.id)
                                 .arg(set)
                                 .arg(now ? QString::number(*now) : QStringLiteral("nothing"),
                                      line.detail);
                }
            }
        }
    };
    check(report.written, Says::New);
    check(report.refused, Says::Old);
    check(report.notWritten, Says::Old);
    check(report.unknown, Says::Either);
    for (const DownloadItem &item : plan.items) {
        if (covered.value(item.id) != wantedSets(item))
            wrong << QStringLiteral("%1: sets %2 reported, %3 to write")
                         .arg(item.id)
                         .arg(covered.value(item.id), 0, 16)
                         .arg(wantedSets(item), 0, 16);
    }
    return wrong.join(QLatin1Char('\n'));
}

} // namespace DriveDesk::DownloadCheck
