// How a ClientWorker opens its link (at a fixed rate or after a baud-rate search), loses it and
// closes it, the states and silence it reports on the way, and the requests a lost link fails.
#include "ClientWorker.h"

#include "BaudRateSearch.h"
#include "ClientTiming.h"

#include <QTimer>

namespace DriveDesk {

void ClientWorker::setState(DriveClient::State state)
{
    if (m_state == state)
        return;
    m_state = state;
    if (state != DriveClient::State::Connected) {
        setDriveSilent(false); // a drive that is not connected is not "silent"
        resetSilence();
    }
    emit stateChanged(state);
}

void ClientWorker::setDriveSilent(bool silent)
{
    if (silent == m_driveSilent)
        return;
    m_driveSilent = silent;
    if (silent) {
        record(TrafficRecord::Kind::Error, {},
               tr("the drive has gone silent: a request was given up after every attempt and "
                  "no valid answer came from the drive since"));
    }
    emit driveSilentChanged(silent);
}

void ClientWorker::connectToDrive()
{
    if (m_state == DriveClient::State::Connecting || m_state == DriveClient::State::Connected)
        return;
    dropLink();
    if (m_settings.kind != ConnectionSettings::Kind::Serial || !m_settings.automaticBaudRate)
        return openLink();
    setState(DriveClient::State::Connecting);
    m_baudSearch = std::make_unique<BaudRateSearch>(m_settings, m_makeLink);
    connect(m_baudSearch.get(), &BaudRateSearch::note, this,
            [this](const QString &text) { record(TrafficRecord::Kind::Error, {}, text); });
    connect(m_baudSearch.get(), &BaudRateSearch::found, this, &ClientWorker::onBaudRateFound);
    connect(m_baudSearch.get(), &BaudRateSearch::failed, this, [this](const QString &reason) {
        m_baudSearch.release()->deleteLater(); // it is reporting right now
        setState(DriveClient::State::Disconnected);
        emit connectionFailed(reason);
        failAll(Reply::Status::NotConnected, reason);
    });
    m_baudSearch->start();
}

void ClientWorker::onBaudRateFound(qint32 baudRate)
{
    m_baudSearch.release()->deleteLater(); // it is reporting right now
    m_settings.baudRate = baudRate;
    m_answerTimeoutMs = DriveDesk::answerTimeoutMs(m_settings, m_options);
    m_quietLineMs = quietLineMs(m_settings);
    emit baudRateFound(baudRate);
    openLink();
}

void ClientWorker::openLink()
{
    m_decoder->reset();
    m_selectedDrive = -1;
    m_recovering = false;
    m_link = m_makeLink ? m_makeLink(m_settings) : nullptr;
    if (!m_link) {
        setState(DriveClient::State::Disconnected);
        emit connectionFailed(tr("%1: this program cannot open such a connection")
                                  .arg(m_settings.displayName()));
        return;
    }
    // What a dropped link still had on its way is not this link's business.
    const quint64 generation = ++m_linkGeneration;
    connect(m_link.get(), &Link::opened, this, &ClientWorker::onLinkOpened);
    connect(m_link.get(), &Link::received, this, [this, generation](const QByteArray &bytes) {
        fromLink(generation, [this, bytes] { onReceived(bytes); });
    });
    connect(m_link.get(), &Link::lineError, this, [this, generation](const QString &reason) {
        fromLink(generation, [this, reason] { onLineError(reason); });
    });
    connect(m_link.get(), &Link::failed, this, [this, generation](const QString &reason) {
        fromLink(generation, [this, reason] { onLinkFailed(reason); });
    });
    setState(DriveClient::State::Connecting);
    m_link->open();
}

void ClientWorker::fromLink(quint64 generation, std::function<void()> report)
{
    auto checked = [this, generation, report = std::move(report)] {
        if (generation == m_linkGeneration)
            report();
    };
    if (!m_inSend && m_linkReportsLater.empty())
        return checked();
    m_linkReportsLater.push_back(std::move(checked));
    if (m_linkReportsLater.size() == 1)
        QMetaObject::invokeMethod(this, &ClientWorker::runLinkReportsLater, Qt::QueuedConnection);
}

void ClientWorker::runLinkReportsLater()
{
    // A report may send, and what the link says then waits behind the ones still here.
    while (!m_linkReportsLater.empty() && !m_inSend) {
        const std::function<void()> report = std::move(m_linkReportsLater.front());
        m_linkReportsLater.erase(m_linkReportsLater.begin());
        report();
    }
}

void ClientWorker::sendToLink(const QByteArray &bytes)
{
    m_inSend = true;
    m_link->send(bytes);
    m_inSend = false;
}

void ClientWorker::disconnectFromDrive()
{
    if (m_baudSearch) {
        m_baudSearch.reset();
        setState(DriveClient::State::Disconnected);
        failAll(Reply::Status::Cancelled, tr("disconnected"));
        return;
    }
    if (!m_link)
        return;
    setState(DriveClient::State::Disconnected);
    dropLink();
    failAll(Reply::Status::Cancelled, tr("disconnected"));
}

void ClientWorker::dropLink()
{
    if (!m_link)
        return;
    ++m_linkGeneration;
    m_link->disconnect(this);
    m_link->close();
    // It may be reporting right now: delete it once its signal returned.
    m_link.release()->deleteLater();
}

void ClientWorker::onLinkOpened()
{
    if (m_state != DriveClient::State::Connecting)
        return;
    m_sinceConnected.start();
    setState(DriveClient::State::Connected);
    emit connected();
    pump();
}

void ClientWorker::onLinkFailed(const QString &reason)
{
    // The state changes first: whatever a completion submits then fails at once.
    if (m_state == DriveClient::State::Connecting) {
        setState(DriveClient::State::Disconnected);
        dropLink();
        emit connectionFailed(reason);
        failAll(Reply::Status::NotConnected, reason);
    } else if (m_state == DriveClient::State::Connected) {
        setState(DriveClient::State::Lost);
        dropLink();
        emit linkLost(reason);
        failAll(Reply::Status::LinkLost, reason);
    }
}

void ClientWorker::failAll(Reply::Status status, const QString &detail)
{
    std::vector<Request> all;
    for (Request &request : m_inFlight)
        all.push_back(std::move(request));
    for (Request &request : m_queue)
        all.push_back(std::move(request));
    m_inFlight.clear();
    m_queue.clear();
    if (m_deadlineTimer)
        m_deadlineTimer->stop();
    for (Request &request : all) {
        if (!request->completed())
            complete(*request, status, nullptr, detail);
    }
}

} // namespace DriveDesk
