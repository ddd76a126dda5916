#include "DriveSession.h"

#include "bus/LinkFactory.h"
#include "client/WhenFinished.h"
#include "state/DriveState.h"
#include "session/ValueReads.h"

namespace DriveDesk {

namespace {

const QString kSetGroup = QStringLiteral("Fr");
constexpr quint8 kActiveSetNumber = 2; // Fr.02
constexpr quint8 kSetPointerNumber = 9; // Fr.09

} // namespace

DriveSession::DriveSession(const ConnectionSettings &settings, DriveState *state,
                           QObject *parent)
    : QObject(parent)
    , m_state(state)
{
    // A drive that freezes while the window only shows it is reported, not left "Connected".
    ClientOptions options;
    options.idleCheckMs = ClientOptions::kInteractiveIdleCheckMs;
    m_client = new DriveClient(settings, everyLink(), options);

    connect(m_client, &DriveClient::stateChanged, this, [this](DriveClient::State state) {
        if (m_reconnecting && state == DriveClient::State::Disconnected) {
            m_reconnecting = false;
            m_client->connectToDrive();
        }
    });
    connect(m_client, &DriveClient::connected, this, &DriveSession::onConnected);
    connect(&m_scan, &QFutureWatcherBase::progressValueChanged, this, [this](int value) {
        emit scanProgress(value, m_scan.progressMaximum(), m_scan.progressText());
    });
    connect(&m_scan, &QFutureWatcherBase::progressTextChanged, this, [this](const QString &text) {
        emit scanProgress(m_scan.progressValue(), m_scan.progressMaximum(), text);
    });
    connect(&m_scan, &QFutureWatcherBase::finished, this, &DriveSession::onScanFinished);
}

DriveSession::~DriveSession()
{
    m_scan.disconnect(this);
    if (m_scan.isRunning())
        m_scan.cancel();
    delete m_client;
}

void DriveSession::start()
{
    m_client->connectToDrive();
}

void DriveSession::reconnect()
{
    const DriveClient::State state = m_client->state();
    if (state != DriveClient::State::Connected && state != DriveClient::State::Connecting) {
        start();
        return;
    }
    m_reconnecting = true;
    disconnectFromDrive();
}

void DriveSession::disconnectFromDrive()
{
    cancelScan();
    emit closing();
    m_client->disconnectFromDrive();
}

void DriveSession::cancelScan()
{
    // Stopped, not cancelled: what the scan has read so far still reaches the table.
    if (m_scan.isRunning())
        m_client->stopScan();
}

void DriveSession::rescan(MetadataSource metadata)
{
    if (m_scan.isRunning() || m_client->state() != DriveClient::State::Connected)
        return;
    ScanOptions options;
    options.metadata = metadata;
    m_scan.setFuture(m_client->scan(options));
    emit scanStarted();
}

void DriveSession::onConnected()
{
    emit connected();
    if (!m_described) {
        rescan();
        return;
    }
    // Back after a lost link: the model still holds what was read; bring the values up to date.
    // The built-in simulated drive is made anew on every connection, with its values from
    // scratch: what was written to the old one is not there to undo.
    if (settings().kind == ConnectionSettings::Kind::Simulated)
        emit writesLost();
    // A table read only in part holds parameters whose metadata never came (no limits, no
    // scaling, no properties): refreshing their values would pass them off as the drive's.
    if (!m_incompleteReason.isEmpty()) {
        rescan();
        return;
    }
    readSetPointers();
    emit ready();
    emit valuesRequested();
}

void DriveSession::onScanFinished()
{
    const QFuture<DriveDescription> future = m_scan.future();
    if (future.isCanceled() || future.resultCount() == 0) {
        if (m_described && m_incompleteReason.isEmpty())
            emit scanDiscarded(tr("the scan was cancelled"));
        else
            emit scanFinished(tr("the scan was cancelled"));
        return;
    }
    const DriveDescription drive = future.result();
    if (!drive.incompleteReason.isEmpty() && m_described && m_incompleteReason.isEmpty()) {
        emit scanDiscarded(drive.incompleteReason);
        return;
    }
    m_activeSet.reset();
    m_setPointer.reset();
    if (const GroupDescription *sets = drive.findGroup(kSetGroup)) {
        const auto address = [&](quint8 number) -> std::optional<quint16> {
            const quint16 a = quint16(sets->address + number);
            return drive.find(a) ? std::optional<quint16>(a) : std::nullopt;
        };
        m_activeSet = address(kActiveSetNumber);
        m_setPointer = address(kSetPointerNumber);
    }
    m_state->setDescription(drive);
    // The idle line's check reads a value the drive has, not address 0000h, which a drive
    // without it refuses every few seconds in the telegram monitor.
    for (const GroupDescription &group : drive.groups) {
        const QList<ValueRead> readable = readableValues(group, m_state->passwordLevel());
        if (!readable.isEmpty()) {
            m_client->setIdleCheckAddress(readable.constFirst().address);
            break;
        }
    }
    m_described = true;
    m_incompleteReason = drive.incompleteReason;
    emit described(drive);
    readSetPointers();
    emit ready();
    emit scanFinished(drive.incompleteReason);
}

void DriveSession::readSetPointers()
{
    for (const std::optional<quint16> &address : { m_activeSet, m_setPointer }) {
        if (!address)
            continue;
        whenFinished(m_client->readValue(*address, 0x01), this, [this](const Reply &reply) {
            if (const auto *value = reply.data<ParameterValue>())
                m_state->setValue(value->address, 0, value->value);
        });
    }
}

int DriveSession::activeSet() const
{
    return m_activeSet ? m_state->value(*m_activeSet, 0).value_or(-1) : -1;
}

bool DriveSession::isReady() const
{
    return m_client->state() == DriveClient::State::Connected && m_described
        && !m_scan.isRunning();
}

void DriveSession::readValuesAgain()
{
    if (m_client->state() != DriveClient::State::Connected)
        return;
    if (!m_described)
        rescan();
    else
        emit valuesRequested();
}

} // namespace DriveDesk
