#pragma once

#include "bus/SimulatorServer.h"
#include "link/ConnectionSettings.h"
#include "protocol/Codec.h"
#include "protocol/din/DinCharacters.h"
#include "protocol/hsp5/Hsp5Codec.h"
#include "protocol/hsp5/Hsp5Layout.h"

#include <QHostAddress>
#include <QPointer>
#include <QRandomGenerator>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

#include <deque>
#include <memory>
#include <utility>

namespace DriveDesk::ClientTest {

// A loopback TCP proxy in front of a drive's TCP server (SimulatorServer::tcpPort()) that passes
// the requests on untouched and spoils every answer on its way back, as a broken gateway, a
// wrong line setting or something that is not a drive would. One connection at a time. Lives
// in the test's thread: it works while the test waits in its event loop.
class SpoilingProxy : public QObject
{
public:
    enum class Spoil : quint8 {
        None,
        Doubled, // every answer sent twice
        CutInHalf, // only the first half of each answer
        Stale, // the answer before it instead (the first: nothing)
        OneByteMore, // a character more in the data, the checksum made right
        OneByteLess, // a character less, the checksum made right
        FlippedBit, // a bit of the data flipped: the checksum wrong
        RandomBytes, // as many random bytes as the answer has
        EndlessRandom, // answers dropped; random bytes at the line's pace, without end
        EndlessDigits, // answers dropped; STX, then digits at the line's pace, without end
        EndlessAck, // answers dropped; "1 ACK" at the line's pace, over and over
        // The answers to writes lost on their way back, every attempt's: the drive took the
        // value, its word on it never came. Every other answer passes.
        WritesUnanswered,
        // HSP5: every text answer's length byte one more than the text it carries, the BCC
        // made right: the decoder reads on into the next answer. Other answers pass.
        TextLengthGrown,
    };

    SpoilingProxy(Protocol protocol, quint16 drivePort, Spoil spoil, QObject *parent = nullptr)
        : QObject(parent)
        , m_protocol(protocol)
        , m_drivePort(drivePort)
        , m_spoil(spoil)
        , m_random(20240611)
    {
        if (protocol == Protocol::Hsp5)
            m_decoder = makeCodec(protocol)->makeDecoder(Role::Operator);
        m_requests = makeCodec(protocol)->makeDecoder(Role::Drive);
        m_stream.setInterval(kStreamIntervalMs);
        connect(&m_stream, &QTimer::timeout, this, &SpoilingProxy::streamOn);
        connect(&m_server, &QTcpServer::newConnection, this, &SpoilingProxy::accept);
    }

    ~SpoilingProxy() override
    {
        // The sockets go with the server member and the QObject base, after the members their
        // slots use (the stream's timer): nothing of theirs may reach this object any more.
        if (m_client)
            m_client->disconnect(this);
        if (m_drive)
            m_drive->disconnect(this);
        m_stream.stop();
    }

    bool listen(QString *error)
    {
        if (m_server.listen(QHostAddress::LocalHost, 0))
            return true;
        *error = m_server.errorString();
        return false;
    }

    // Where the drive's server is, when it was not known at construction.
    void setDrivePort(quint16 port) { m_drivePort = port; }

    // A client's way to the drive through the proxy.
    ConnectionSettings settings() const
    {
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = m_server.serverPort();
        settings.protocol = m_protocol;
        return settings;
    }

    // From the next answer on; an endless stream stops.
    void setSpoil(Spoil spoil)
    {
        m_spoil = spoil;
        m_stream.stop();
        m_previous.clear();
    }

    int answersSeen() const { return m_answers; }

private:
    // 38400 Bd at 10 bits a character: 38 characters each 10 ms.
    static constexpr int kStreamIntervalMs = 10;
    static constexpr int kStreamCharacters = 38;

    void accept()
    {
        while (QTcpSocket *socket = m_server.nextPendingConnection()) {
            if (m_client) {
                socket->close();
                socket->deleteLater();
                continue;
            }
            m_client = socket;
            m_drive = new QTcpSocket(this);
            connect(m_drive, &QTcpSocket::connected, this, [this] {
                m_drive->write(m_toDrive);
                m_toDrive.clear();
            });
            connect(m_drive, &QTcpSocket::readyRead, this,
                    [this] { fromDrive(m_drive->readAll()); });
            connect(m_client, &QTcpSocket::readyRead, this, [this] {
                const QByteArray bytes = m_client->readAll();
                // The drive answers in the order it was asked: which answer is a write's.
                m_requests->feed(bytes);
                while (const std::optional<Decoded> item = m_requests->next()) {
                    if (const auto *request = std::get_if<Telegram>(&*item))
                        m_writes.push_back(request->isWrite());
                }
                if (m_drive->state() == QAbstractSocket::ConnectedState)
                    m_drive->write(bytes);
                else
                    m_toDrive.append(bytes);
            });
            connect(m_client, &QTcpSocket::disconnected, this, [this] {
                m_stream.stop();
                m_drive->disconnectFromHost();
                m_drive->deleteLater();
                m_client->deleteLater();
            });
            m_drive->connectToHost(QHostAddress::LocalHost, m_drivePort);
        }
    }

    void fromDrive(const QByteArray &bytes)
    {
        m_fromDrive.append(bytes);
        if (m_decoder)
            m_decoder->feed(bytes);
        while (true) {
            const QByteArray answer = m_decoder ? nextHsp5Answer() : nextDinAnswer();
            if (answer.isEmpty())
                return;
            ++m_answers;
            const bool toWrite = !m_writes.empty() && m_writes.front();
            if (!m_writes.empty())
                m_writes.pop_front();
            if (m_spoil == Spoil::WritesUnanswered) {
                if (!toWrite)
                    toClient(answer);
                continue;
            }
            toClient(spoiled(answer));
        }
    }

    // The raw bytes of the next telegram the drive sent, or nothing until it is complete.
    QByteArray nextHsp5Answer()
    {
        if (!m_decoder->next())
            return {};
        const qsizetype length = m_fromDrive.size() - m_decoder->buffered();
        const QByteArray answer = m_fromDrive.left(length);
        m_fromDrive.remove(0, length);
        return answer;
    }

    // STX ... ETX BCC, or a short answer: up to ACK, NAK or EOT.
    QByteArray nextDinAnswer()
    {
        qsizetype end = -1;
        if (!m_fromDrive.isEmpty() && m_fromDrive.front() == DinControl::Stx) {
            const qsizetype etx = m_fromDrive.indexOf(DinControl::Etx);
            if (etx >= 0 && etx + 1 < m_fromDrive.size())
                end = etx + 2;
        } else {
            for (qsizetype i = 0; i < m_fromDrive.size() && end < 0; ++i) {
                const char c = m_fromDrive.at(i);
                if (c == DinControl::Ack || c == DinControl::Nak || c == DinControl::Eot)
                    end = i + 1;
            }
        }
        if (end < 0)
            return {};
        const QByteArray answer = m_fromDrive.left(end);
        m_fromDrive.remove(0, end);
        return answer;
    }

    QByteArray spoiled(const QByteArray &answer)
    {
        switch (m_spoil) {
        case Spoil::None:
        case Spoil::WritesUnanswered: // decided in fromDrive()
            return answer;
        case Spoil::Doubled:
            return answer + answer;
        case Spoil::CutInHalf:
            return answer.left(answer.size() / 2);
        case Spoil::Stale:
            return std::exchange(m_previous, answer);
        case Spoil::OneByteMore:
            return resized(answer, +1);
        case Spoil::OneByteLess:
            return resized(answer, -1);
        case Spoil::FlippedBit:
            return flipped(answer);
        case Spoil::TextLengthGrown:
            return textLengthGrown(answer);
        case Spoil::RandomBytes:
            return randomBytes(answer.size());
        case Spoil::EndlessRandom:
        case Spoil::EndlessDigits:
        case Spoil::EndlessAck:
            if (!m_stream.isActive()) {
                m_streamed = 0;
                m_stream.start();
            }
            return {};
        }
        return answer;
    }

    // The answer with a character more or less in its data and the checksum made right again.
    QByteArray resized(const QByteArray &answer, int by) const
    {
        if (m_protocol == Protocol::Hsp5) {
            // Invoke ids and service, data, acknowledge, BCC: the data starts at byte 2.
            QByteArray telegram = answer.chopped(1);
            if (by > 0)
                telegram.insert(2, '\0');
            else if (telegram.size() > 3)
                telegram.remove(2, 1);
            return telegram.append(char(hsp5Bcc(telegram)));
        }
        if (answer.front() != DinControl::Stx) {
            // A short answer has no checksum: a character more or less before its end.
            QByteArray shortAnswer = answer;
            if (by > 0)
                shortAnswer.prepend('0');
            else if (shortAnswer.size() > 1)
                shortAnswer.remove(0, 1);
            return shortAnswer;
        }
        QByteArray covered = answer.mid(1, answer.size() - 3); // the characters up to ETX
        if (by > 0)
            covered.append('0');
        else
            covered.chop(1);
        covered.append(DinControl::Etx);
        return QByteArray(1, DinControl::Stx) + covered + char(dinBcc(covered));
    }

    QByteArray textLengthGrown(QByteArray answer) const
    {
        if (m_protocol != Protocol::Hsp5 || answer.size() < 3)
            return answer;
        const std::optional<Service> service = hsp5Service(quint8(answer.at(1)) & 0x3F);
        const std::optional<Hsp5Layout> layout
            = service ? hsp5Layout(*service, Access::Read, Direction::Response) : std::nullopt;
        if (!layout || layout->maxCount != kHsp5MaxText || layout->countByte >= answer.size() - 1)
            return answer;
        answer[layout->countByte] = char(answer.at(layout->countByte) + 1);
        answer.chop(1);
        return answer.append(char(hsp5Bcc(answer)));
    }

    // Bit 0 of a data character flipped: HSP5 byte 2, DIN66019II the character before ETX. A
    // short answer has no checksum and stays as it is.
    QByteArray flipped(QByteArray answer) const
    {
        const bool frame = m_protocol == Protocol::Hsp5 || answer.front() == DinControl::Stx;
        const qsizetype at = m_protocol == Protocol::Hsp5 ? 2 : answer.size() - 3;
        if (frame && at > 0 && at < answer.size())
            answer[at] = char(answer.at(at) ^ 0x01);
        return answer;
    }

    QByteArray randomBytes(qsizetype count)
    {
        QByteArray bytes(count, '\0');
        for (char &byte : bytes)
            byte = char(m_random.bounded(256));
        return bytes;
    }

    void streamOn()
    {
        if (!m_client)
            return;
        QByteArray bytes;
        switch (m_spoil) {
        case Spoil::EndlessDigits:
            for (int i = 0; i < kStreamCharacters; ++i, ++m_streamed)
                bytes.append(m_streamed == 0 ? DinControl::Stx : char('0' + m_streamed % 10));
            break;
        case Spoil::EndlessAck:
            for (int i = 0; i < kStreamCharacters / 2; ++i)
                bytes.append('1').append(DinControl::Ack);
            break;
        default:
            bytes = randomBytes(kStreamCharacters);
            break;
        }
        toClient(bytes);
    }

    void toClient(const QByteArray &bytes)
    {
        if (m_client && !bytes.isEmpty())
            m_client->write(bytes);
    }

    const Protocol m_protocol;
    quint16 m_drivePort;
    Spoil m_spoil;
    QRandomGenerator m_random;
    std::unique_ptr<FrameDecoder> m_decoder; // HSP5: where a telegram ends
    std::unique_ptr<FrameDecoder> m_requests; // the requests, as the drive reads them
    std::deque<bool> m_writes; // per request not yet answered: whether it is a write
    QTcpServer m_server;
    QPointer<QTcpSocket> m_client;
    QPointer<QTcpSocket> m_drive;
    QByteArray m_toDrive; // requests before the drive's connection is up
    QByteArray m_fromDrive; // what the drive sent that is not yet a whole answer
    QByteArray m_previous; // Stale: the answer held back
    QTimer m_stream;
    qint64 m_streamed = 0;
    int m_answers = 0;
};

// The simulated drive behind its TCP server, and the proxy in front of it: what a test of a
// spoilt line starts with.
struct ProxiedDrive
{
    SimulatorServer server;
    SpoilingProxy proxy;

    ProxiedDrive(Protocol protocol, const SimulationOptions &options, SpoilingProxy::Spoil spoil)
        : server(protocol, options)
        , proxy(protocol, 0, spoil)
    {}

    // Both listening on loopback; false with the reason when either cannot.
    bool listen(QString *error)
    {
        if (!server.listenTcp(QStringLiteral("127.0.0.1"), 0, error))
            return false;
        proxy.setDrivePort(server.tcpPort());
        return proxy.listen(error);
    }
};

} // namespace DriveDesk::ClientTest
