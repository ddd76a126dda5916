#pragma once

#include "bus/LinkFactory.h"
#include "client/DriveClient.h"
#include "model/ParameterModel.h"

#include <QFutureWatcher>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <optional>

// What the editing tests share: the simulated F5 in process behind a real DriveClient, and a
// ParameterModel filled by the client's scan, as the main window sets them up.
namespace DriveDesk::EditTest {

constexpr int kWaitMs = 20000;

// Parameters of the simulated F5 (core/sim/data/sim_f5_parameters.csv) the tests rely on.
constexpr quint16 kActualFrequency = 0x0203; // ru.03, read-only, live
constexpr quint16 kDemoPeriod = 0x0305; // op.05, one value, 4.0..600.0 s, default 20.0
constexpr quint16 kMaxSpeedForward = 0x030B; // op.11, 0..4000 rpm, default 3000, 8 sets
constexpr quint16 kFixedSpeed1 = 0x0314; // op.20, -4000..4000 rpm, default 100, 8 sets
constexpr quint16 kControlMode = 0x0700; // cn.00, written at Drive mode (4)
constexpr quint16 kCalibration = 0x0E28; // In.40, read at Security (6)
constexpr quint16 kPassword = 0x0801; // ud.01

inline ConnectionSettings simulated(int replyLatencyUs = 0)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.simulation.replyLatencyUs = replyLatencyUs;
    return settings;
}

template<typename T> bool waitFinished(const QFuture<T> &future)
{
    return QTest::qWaitFor([&future] { return future.isFinished(); }, kWaitMs);
}

// A connected client and the model of what its scan found.
struct SimulatedDrive
{
    DriveClient client;
    ParameterModel model;
    QUndoStack undoStack;

    explicit SimulatedDrive(int replyLatencyUs = 0)
        : client(simulated(replyLatencyUs), everyLink())
    { }
    explicit SimulatedDrive(const ConnectionSettings &settings)
        : client(settings, everyLink())
    { }

    // Connects and scans (values, no plaintexts; every group, or those of the pages given);
    // false when either did not work.
    bool start(const QList<quint8> &groupPages = {})
    {
        client.connectToDrive();
        if (!QTest::qWaitFor([this] { return client.state() == DriveClient::State::Connected; },
                             kWaitMs)) {
            return false;
        }
        ScanOptions options;
        options.plaintexts = false;
        options.groupPages = groupPages;
        const QFuture<DriveDescription> scan = client.scan(options);
        if (!waitFinished(scan) || scan.resultCount() == 0)
            return false;
        model.state()->setDescription(scan.result());
        return model.rowCount() > 0;
    }

    Reply call(const QFuture<Reply> &future)
    {
        if (!waitFinished(future) || future.resultCount() == 0)
            return {};
        return future.result();
    }

    // Sends a read of ud.01 and waits until its reply arrives in this thread. By then every
    // request sent before it has been answered, its reply handled here and its traffic (and this
    // read's own) delivered: the drive answers in order, and the client hands this thread what
    // happened in the order it happened.
    bool answerToALaterRead()
    {
        QFutureWatcher<Reply> later;
        QSignalSpy answered(&later, &QFutureWatcherBase::finished);
        later.setFuture(client.readValueStandard(kPassword, 0));
        return QTest::qWaitFor([&answered] { return !answered.isEmpty(); }, kWaitMs);
    }

    // What the drive holds, read past the model.
    std::optional<qint32> driveValue(quint16 address, int set = 0)
    {
        const Reply reply = call(client.readValue(address, quint8(1u << set)));
        if (const auto *value = reply.data<ParameterValue>())
            return value->value;
        return std::nullopt;
    }

    bool setDriveValue(quint16 address, int set, qint32 raw)
    {
        return call(client.writeValue(address, raw, quint8(1u << set))).ok();
    }

    EditState state(quint16 address, int set = 0) const { return model.state()->editState(address, set); }
    QString toolTip(quint16 address, int set = 0) const
    {
        return model.valueIndex(address, set).data(Qt::ToolTipRole).toString();
    }
};

// How many records of a kind a spy on DriveClient::traffic holds.
inline int records(const QSignalSpy &traffic, TrafficRecord::Kind kind)
{
    int count = 0;
    for (const QList<QVariant> &arguments : traffic) {
        if (arguments.at(0).value<TrafficRecord>().kind == kind)
            ++count;
    }
    return count;
}

inline QStringList texts(const QSignalSpy &spy)
{
    QStringList list;
    for (const QList<QVariant> &arguments : spy)
        list << arguments.at(0).toString();
    return list;
}

} // namespace DriveDesk::EditTest
