// The longest stall of the window's event loop while it scans a simulated drive of 5,000
// parameters (filling the model included) and while it polls the run display every 100 ms for
// 10 s. A 1 ms timer measures the gaps between its own ticks. Also the time the window takes
// for each keystroke of a search over all 5,000. Prints figures; asserts nothing.
// Goals: no stall longer than 50 ms; a keystroke under 30 ms. Runs offscreen unless
// QT_QPA_PLATFORM says otherwise.
#include "edit/PollingController.h"
#include "frame/DriveSession.h"
#include "frame/ParameterBrowser.h"
#include "main/MainWindow.h"
#include "model/ParameterModel.h"

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace DriveDesk;

namespace {

constexpr int kParameters = 5000;
constexpr int kPollingIntervalMs = 100;
constexpr int kPollingMs = 10000;

// Ticks every millisecond and remembers the gaps between ticks of the current phase.
class StallMeter : public QObject
{
public:
    StallMeter()
    {
        m_timer.setTimerType(Qt::PreciseTimer);
        m_timer.setInterval(1);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            const qint64 now = m_clock.nsecsElapsed();
            m_gapsNs.push_back(now - m_lastNs);
            m_lastNs = now;
        });
    }
    void start()
    {
        m_gapsNs.clear();
        m_clock.start();
        m_lastNs = 0;
        m_timer.start();
    }
    double elapsedMs() const { return double(m_clock.nsecsElapsed()) / 1e6; }
    double longestMs() const
    {
        return m_gapsNs.empty() ? 0
                                : double(*std::max_element(m_gapsNs.begin(), m_gapsNs.end())) / 1e6;
    }
    double percentileMs(double p) const
    {
        if (m_gapsNs.empty())
            return 0;
        std::vector<qint64> sorted = m_gapsNs;
        std::sort(sorted.begin(), sorted.end());
        return double(sorted[std::size_t(p * double(sorted.size() - 1))]) / 1e6;
    }
    std::size_t over(double ms) const
    {
        return std::size_t(std::count_if(m_gapsNs.begin(), m_gapsNs.end(),
                                         [ms](qint64 gap) { return double(gap) / 1e6 > ms; }));
    }
    std::size_t ticks() const { return m_gapsNs.size(); }

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    std::vector<qint64> m_gapsNs;
};

// Types `text` into the search field one character at a time, then clears it; the slowest step.
double slowestKeystrokeMs(QLineEdit *field, const QString &text)
{
    double slowest = 0;
    QElapsedTimer clock;
    for (qsizetype length = 1; length <= text.size() + 1; ++length) {
        clock.start();
        field->setText(length <= text.size() ? text.left(length) : QString());
        slowest = std::max(slowest, double(clock.nsecsElapsed()) / 1e6);
    }
    return slowest;
}

void report(const char *phase, const StallMeter &meter)
{
    std::printf("%-44s %8.0f ms  longest stall %6.1f ms  99th %5.1f ms  >16 ms: %zu  >50 ms: %zu  "
                "(%zu ticks)\n",
                phase, meter.elapsedMs(), meter.longestMs(), meter.percentileMs(0.99),
                meter.over(16), meter.over(50), meter.ticks());
    std::fflush(stdout);
}

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QTemporaryDir settingsDir; // the benchmark leaves the user's settings alone
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QApplication::setOrganizationName(QStringLiteral("DriveDesk"));
    QApplication::setApplicationName(QStringLiteral("DriveDesk benchmark"));

    MainWindow window;
    window.resize(1400, 900);
    window.show();

    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.simulation.parameterCount = kParameters;
    settings.simulation.replyLatencyUs = 0; // answers as fast as the client takes them

    StallMeter meter;
    std::printf("bench_gui_stall: the window's event loop, simulated drive of %d parameters "
                "(goal: longest stall < 50 ms)\n",
                kParameters);

    QObject::connect(&window, &MainWindow::driveRead, &app, [&] {
        int parameters = 0;
        for (int group = 0; group < window.model()->rowCount(); ++group)
            parameters += window.model()->rowCount(window.model()->index(group, 0));
        report(qPrintable(QStringLiteral("scan of %1 parameters, model filled").arg(parameters)),
               meter);

        const QString typed = QStringLiteral("motor 1");
        std::printf("%-44s slowest keystroke %.1f ms (goal < 30 ms)\n",
                    qPrintable(QStringLiteral("search \"%1\" over all parameters").arg(typed)),
                    slowestKeystrokeMs(window.browser()->searchField(), typed));

        window.browser()->showGroup(QStringLiteral("ru"));
        for (QAction *action : window.findChildren<QAction *>()) {
            if (action->data().toInt() == kPollingIntervalMs && action->isCheckable())
                action->trigger();
        }
        window.findChild<QAction *>(QStringLiteral("pollingAction"))->setChecked(true);
        meter.start();
        QTimer::singleShot(kPollingMs, &app, [&] {
            auto *polling = window.findChild<PollingController *>();
            report(qPrintable(QStringLiteral("polling ru every %1 ms (%2 rounds, %3 skipped)")
                                  .arg(kPollingIntervalMs)
                                  .arg(polling->roundsCompleted())
                                  .arg(polling->roundsSkipped())),
                   meter);
            QApplication::quit();
        });
    });

    QTimer::singleShot(0, &app, [&] {
        meter.start();
        window.connectTo(settings);
    });
    return app.exec();
}
