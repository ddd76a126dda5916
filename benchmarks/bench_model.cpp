// The parameter model with 5,000 parameters: filling it, filter keystrokes, a polling burst.
// Prints figures; asserts nothing. Goals: fill < 100 ms, each keystroke < 30 ms.
#include "model/ParameterFilterModel.h"
#include "model/ParameterModel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTextStream>
#include <QTreeView>

#include <cstdio>

using namespace DriveDesk;

namespace {

constexpr int kGroups = 50;
constexpr int kPerGroup = 100; // 5,000 parameters

const char *const kWords[] = { "Motor", "frequency", "ramp",   "time",  "current", "voltage",
                               "limit", "speed",     "torque", "brake", "input",   "output" };

DriveDescription bigDrive()
{
    DriveDescription drive;
    drive.protocol = QStringLiteral("hsp5");
    for (int g = 0; g < kGroups; ++g) {
        GroupDescription group;
        group.address = quint16((g + 1) << 8);
        group.index = quint8(g);
        group.id = QStringLiteral("%1%2").arg(QChar(u'A' + g % 26)).arg(QChar(u'a' + g / 26));
        group.name = QStringLiteral("Group %1").arg(g);
        for (int n = 0; n < kPerGroup; ++n) {
            ParameterDescription p;
            p.address = quint16(group.address + n);
            p.name = QStringLiteral("%1 %2 %3")
                         .arg(QString::fromLatin1(kWords[(g + n) % 12]),
                              QString::fromLatin1(kWords[(n * 7) % 12]))
                         .arg(n);
            p.minimum = -100000;
            p.maximum = 100000;
            p.defaultValue = n * 10;
            p.properties1 = n % 3 == 0 ? 1u << 11 : 0u;
            p.properties2 = 0x0F;
            p.scaling = { p.address, qint16(n % 4 == 0 ? 1 : 100), 1, 0,
                          quint16((n % 40) | ((n % 5) << 8)) };
            if (n % 10 == 7) {
                p.plaintexts = { { 0,
                                   QString(),
                                   { { 0, 0, QStringLiteral("off") },
                                     { 1, 0, QStringLiteral("on") },
                                     { 2, 0, QStringLiteral("auto") } } } };
            }
            // Every other parameter holds its default.
            for (int set = 0; set < (p.isSetProgrammable() ? kParameterSets : 1); ++set) {
                p.values[std::size_t(set)]
                    = n % 2 ? (n * 37 + set * 11 + g) % (n % 10 == 7 ? 3 : 9000) : p.defaultValue;
            }
            group.parameters << p;
        }
        drive.groups << group;
    }
    return drive;
}

int visibleParameters(const QAbstractItemModel &model)
{
    int count = 0;
    for (int g = 0; g < model.rowCount(); ++g)
        count += model.rowCount(model.index(g, 0));
    return count;
}

void print(const QString &line)
{
    std::printf("%s\n", qPrintable(line));
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    const DriveDescription drive = bigDrive();
    print(QStringLiteral("%1 groups, %2 parameters")
              .arg(drive.groups.size())
              .arg(drive.parameterCount()));

    QElapsedTimer timer;
    {
        ParameterModel model;
        timer.start();
        model.state()->setDescription(drive);
        print(QStringLiteral("fill, model alone:            %1 ms (goal < 100 ms)")
                  .arg(timer.nsecsElapsed() / 1e6, 0, 'f', 1));
    }

    ParameterModel model;
    ParameterFilterModel filter;
    filter.setSourceModel(&model);
    QTreeView view;
    view.setModel(&filter);
    view.resize(1200, 800);

    timer.start();
    model.state()->setDescription(drive);
    const int all = visibleParameters(filter);
    print(QStringLiteral("fill, with filter and view:   %1 ms (%2 rows mapped)")
              .arg(timer.nsecsElapsed() / 1e6, 0, 'f', 1)
              .arg(all));

    const QStringList searches { QStringLiteral("m"),
                                 QStringLiteral("mo"),
                                 QStringLiteral("mot"),
                                 QStringLiteral("moto"),
                                 QStringLiteral("motor"),
                                 QStringLiteral("motor "),
                                 QStringLiteral("motor s"),
                                 QStringLiteral("motor sp"),
                                 QStringLiteral("c"),
                                 QStringLiteral("ca"),
                                 QStringLiteral("ca."),
                                 QStringLiteral("ca.1"),
                                 QStringLiteral("ca.17"),
                                 QStringLiteral("5"),
                                 QStringLiteral("50"),
                                 QStringLiteral("50."),
                                 QStringLiteral("50.0"),
                                 QStringLiteral("xyz"),
                                 QString() };
    // The proxy maps a group's rows when first asked for them: each figure includes asking
    // for every row, as a view with every group expanded does.
    double worst = 0;
    for (const QString &text : searches) {
        timer.start();
        filter.setFilterText(text);
        const int shown = visibleParameters(filter);
        const double ms = timer.nsecsElapsed() / 1e6;
        worst = std::max(worst, ms);
        print(QStringLiteral("keystroke %1 %2 ms, %3 parameters shown")
                  .arg(QStringLiteral("'%1'").arg(text), -12)
                  .arg(ms, 6, 'f', 2)
                  .arg(shown));
    }
    print(
        QStringLiteral("slowest keystroke:            %1 ms (goal < 30 ms)").arg(worst, 0, 'f', 2));

    timer.start();
    filter.setDiffersFromDefaultOnly(true);
    const int differing = visibleParameters(filter);
    print(QStringLiteral("differs-from-default filter:  %1 ms, %2 parameters shown")
              .arg(timer.nsecsElapsed() / 1e6, 0, 'f', 2)
              .arg(differing));
    filter.setDiffersFromDefaultOnly(false);

    // Polling one group a few times a second, with a search on: 10 rounds of 100 values.
    filter.setFilterText(QStringLiteral("a"));
    const GroupDescription &polled = drive.groups.first();
    int updates = 0;
    timer.start();
    for (int round = 0; round < 10; ++round) {
        for (const ParameterDescription &p : polled.parameters) {
            model.state()->setValue(p.address, 0, round * 13 + p.number());
            ++updates;
        }
    }
    const double burst = timer.nsecsElapsed() / 1e3;
    print(QStringLiteral("polling burst: %1 updates in %2 ms, %3 us each")
              .arg(updates)
              .arg(burst / 1e3, 0, 'f', 2)
              .arg(burst / updates, 0, 'f', 1));
    return 0;
}
