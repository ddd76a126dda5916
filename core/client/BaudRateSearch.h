#pragma once

#include "link/ConnectionSettings.h"
#include "link/Link.h"
#include "protocol/Codec.h"

#include <QList>
#include <QObject>

#include <memory>

class QTimer;

namespace DriveDesk {

// Finds the baud rate a drive on a serial line talks at: opens the line at each usual rate in
// turn, from the most likely, sends one request any drive answers (the drive search's probe,
// a service the seeds promise for the protocol), and settles on the first rate that brings a
// valid answer to it. A drive at another rate hears noise it cannot frame and stays quiet.
// Thread: the client's worker; the links it makes live and end there.
class BaudRateSearch : public QObject
{
    Q_OBJECT
public:
    BaudRateSearch(ConnectionSettings settings, LinkMaker makeLink, QObject *parent = nullptr);
    ~BaudRateSearch() override;

    void start();

    // The rates tried, most likely first. HSP5: 38400, the rate after power-on, then the
    // rates the drive offers (PROTOCOL-NOTES); DIN66019(II): the typical 9600..38400 (seed
    // 003), then the faster common ones.
    static QList<qint32> candidates(Protocol protocol);

signals:
    void found(qint32 baudRate);
    // No rate brought an answer, or the port cannot be opened at all.
    void failed(const QString &reason);
    // A note for the telegram monitor: which rate is being tried.
    void note(const QString &text);

private:
    void tryNext();
    void onOpened();
    void onReceived(const QByteArray &bytes);
    void dropLink();

    ConnectionSettings m_settings;
    const LinkMaker m_makeLink;
    const std::unique_ptr<ProtocolCodec> m_codec;
    std::unique_ptr<FrameDecoder> m_decoder;
    std::unique_ptr<Link> m_link;
    QTimer *m_timer = nullptr; // no answer at this rate in time
    QList<qint32> m_rates;
    qsizetype m_next = 0;
    Telegram m_probe; // as sent, for checking the answer
    bool m_done = false;
};

} // namespace DriveDesk
