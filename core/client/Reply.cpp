#include "Reply.h"

namespace DriveDesk {

namespace {

QString withDetail(const QString &sentence, const QString &detail)
{
    if (detail.isEmpty())
        return sentence;
    return QStringLiteral("%1 (%2)").arg(sentence, detail);
}

QString englishMessage(const Reply &reply)
{
    switch (reply.status) {
    case Reply::Status::Ok:
        return QStringLiteral("OK");
    case Reply::Status::Refused:
        if (reply.attempts > 1 && isTransient(reply.ack())) {
            return QStringLiteral("drive refused: %1 (after %2 attempts)")
                .arg(ackText(reply.ack(), Language::English))
                .arg(reply.attempts);
        }
        return QStringLiteral("drive refused: %1").arg(ackText(reply.ack(), Language::English));
    case Reply::Status::Timeout:
        return withDetail(reply.attempts == 1
                              ? QStringLiteral("no valid answer from the drive")
                              : QStringLiteral("no valid answer from the drive after %1 attempts")
                                    .arg(reply.attempts),
                          reply.detail);
    case Reply::Status::LinkLost:
        return withDetail(QStringLiteral("the connection to the drive was lost"), reply.detail);
    case Reply::Status::Cancelled:
        return withDetail(QStringLiteral("cancelled"), reply.detail);
    case Reply::Status::NotConnected:
        return withDetail(QStringLiteral("not connected to a drive"), reply.detail);
    case Reply::Status::Unsupported:
        return withDetail(QStringLiteral("this request cannot be sent"), reply.detail);
    case Reply::Status::NoReply:
        return QStringLiteral("sent to a group of drives or to all drives, which never answer: "
                              "carried out, not confirmed");
    }
    return statusName(reply.status);
}

QString germanMessage(const Reply &reply)
{
    switch (reply.status) {
    case Reply::Status::Ok:
        return QStringLiteral("OK");
    case Reply::Status::Refused:
        if (reply.attempts > 1 && isTransient(reply.ack())) {
            return QStringLiteral("Umrichter lehnt ab: %1 (nach %2 Versuchen)")
                .arg(ackText(reply.ack(), Language::German))
                .arg(reply.attempts);
        }
        return QStringLiteral("Umrichter lehnt ab: %1").arg(ackText(reply.ack(), Language::German));
    case Reply::Status::Timeout:
        return withDetail(reply.attempts == 1
                              ? QStringLiteral("keine gültige Antwort vom Umrichter")
                              : QStringLiteral("keine gültige Antwort vom Umrichter nach %1 "
                                               "Versuchen")
                                    .arg(reply.attempts),
                          reply.detail);
    case Reply::Status::LinkLost:
        return withDetail(QStringLiteral("die Verbindung zum Umrichter ist abgebrochen"),
                          reply.detail);
    case Reply::Status::Cancelled:
        return withDetail(QStringLiteral("abgebrochen"), reply.detail);
    case Reply::Status::NotConnected:
        return withDetail(QStringLiteral("nicht mit einem Umrichter verbunden"), reply.detail);
    case Reply::Status::Unsupported:
        return withDetail(QStringLiteral("diese Anfrage kann nicht gesendet werden"), reply.detail);
    case Reply::Status::NoReply:
        return QStringLiteral("an eine Gruppe oder an alle Umrichter gesendet, die nie antworten: "
                              "ausgeführt, nicht bestätigt");
    }
    return statusName(reply.status);
}

} // namespace

QString Reply::message(Language language) const
{
    return language == Language::German ? germanMessage(*this) : englishMessage(*this);
}

QString statusName(Reply::Status status)
{
    switch (status) {
    case Reply::Status::Ok: return QStringLiteral("ok");
    case Reply::Status::Refused: return QStringLiteral("refused");
    case Reply::Status::Timeout: return QStringLiteral("timeout");
    case Reply::Status::LinkLost: return QStringLiteral("link lost");
    case Reply::Status::Cancelled: return QStringLiteral("cancelled");
    case Reply::Status::NotConnected: return QStringLiteral("not connected");
    case Reply::Status::Unsupported: return QStringLiteral("unsupported");
    case Reply::Status::NoReply: return QStringLiteral("no reply");
    }
    return QStringLiteral("status %1").arg(int(status));
}

} // namespace DriveDesk
