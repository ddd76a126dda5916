#include "BaudRateSearch.h"

#include "ClientTiming.h"
#include "ReplyCheck.h"
#include "ValueRequests.h"

#include <QStringList>
#include <QTimer>

namespace DriveDesk {

BaudRateSearch::BaudRateSearch(ConnectionSettings settings, LinkMaker makeLink, QObject *parent)
    : QObject(parent)
    , m_settings(std::move(settings))
    , m_makeLink(std::move(makeLink))
    , m_codec(makeCodec(m_settings.protocol, CodecOptions { m_settings.hsp5Extensions }))
    , m_decoder(m_codec->makeDecoder(Role::Operator))
    , m_rates(candidates(m_settings.protocol))
{
    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, &BaudRateSearch::tryNext);
}

BaudRateSearch::~BaudRateSearch()
{
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
    }
}

QList<qint32> BaudRateSearch::candidates(Protocol protocol)
{
    if (protocol == Protocol::Hsp5)
        return { 38400, 19200, 9600, 57600, 115200, 55500, 100000, 125000, 250000 };
    return { 38400, 19200, 9600, 57600, 115200 };
}

void BaudRateSearch::start()
{
    m_next = 0;
    tryNext();
}

void BaudRateSearch::dropLink()
{
    if (!m_link)
        return;
    m_link->disconnect(this);
    m_link->close();
    // It may be reporting right now: delete it once its signal returned.
    m_link.release()->deleteLater();
}

void BaudRateSearch::tryNext()
{
    dropLink();
    if (m_done)
        return;
    if (m_next >= m_rates.size()) {
        m_done = true;
        QStringList tried;
        for (qint32 rate : std::as_const(m_rates))
            tried << QString::number(rate);
        emit failed(tr("%1: no drive answered at %2 Bd")
                        .arg(m_settings.device, tried.join(QStringLiteral(", "))));
        return;
    }
    m_settings.baudRate = m_rates.at(m_next++);
    m_decoder->reset();
    m_link = m_makeLink ? m_makeLink(m_settings) : nullptr;
    if (!m_link) {
        m_done = true;
        emit failed(
            tr("%1: this program cannot open such a connection").arg(m_settings.displayName()));
        return;
    }
    connect(m_link.get(), &Link::opened, this, &BaudRateSearch::onOpened);
    connect(m_link.get(), &Link::received, this, &BaudRateSearch::onReceived, Qt::QueuedConnection);
    // A port that cannot be opened at one rate cannot be opened at any: that ends the search.
    connect(
        m_link.get(), &Link::failed, this,
        [this](const QString &reason) {
            if (m_done)
                return;
            m_done = true;
            m_timer->stop();
            dropLink();
            emit failed(reason);
        },
        Qt::QueuedConnection);
    m_link->open();
}

void BaudRateSearch::onOpened()
{
    if (m_done || !m_link)
        return;
    emit note(tr("looking for the drive at %1 Bd").arg(m_settings.baudRate));
    m_probe = ValueRequests::presence(m_settings.protocol);
    m_probe.direction = Direction::Request;
    m_probe.operatorInvoke = carriesInvokeId(m_settings.protocol, m_probe.service) ? 1 : 0;
    m_probe.driveAddress = m_settings.protocol == Protocol::Hsp5 ? -1 : m_settings.driveAddress;
    m_link->send(m_codec->encode(m_probe));
    m_timer->start(answerTimeoutMs(m_settings, ClientOptions {}));
}

void BaudRateSearch::onReceived(const QByteArray &bytes)
{
    if (m_done || !m_link)
        return;
    m_decoder->feed(bytes);
    while (const std::optional<Decoded> item = m_decoder->next()) {
        const auto *answer = std::get_if<Telegram>(&*item);
        // Noise at a wrong rate may pass for a telegram now and then; a valid answer to the
        // probe, with its checksum, invoke id and service, does not.
        if (!answer || !answer->isResponse()
            || !replyMismatch(m_settings.protocol, m_probe, *answer).isEmpty())
            continue;
        m_done = true;
        m_timer->stop();
        dropLink();
        emit found(m_settings.baudRate);
        return;
    }
}

} // namespace DriveDesk
