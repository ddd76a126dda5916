#include "Reply.h"

#include <QCoreApplication>

namespace DriveDesk {

namespace {

// The translation context of the messages: Reply is a plain value type.
class ReplyText
{
    Q_DECLARE_TR_FUNCTIONS(Reply)
};

QString withDetail(const QString &sentence, const QString &detail)
{
    if (detail.isEmpty())
        return sentence;
    return QStringLiteral("%1 (%2)").arg(sentence, detail);
}

} // namespace

bool Reply::isAnswer() const
{
    return status == Status::Ok || (status == Status::Refused && !isTransient(ack()));
}

QString Reply::message() const
{
    switch (status) {
    case Status::Ok:
        return ReplyText::tr("OK");
    case Status::Refused:
        if (attempts > 1 && isTransient(ack()))
            return ReplyText::tr("drive refused: %1 (after %n attempt(s))", nullptr, attempts)
                .arg(ackText(ack()));
        return ReplyText::tr("drive refused: %1").arg(ackText(ack()));
    case Status::Timeout:
        return withDetail(attempts == 1
                              ? ReplyText::tr("no valid answer from the drive")
                              : ReplyText::tr("no valid answer from the drive after %n attempt(s)",
                                              nullptr, attempts),
                          detail);
    case Status::LinkLost:
        return withDetail(ReplyText::tr("the connection to the drive was lost"), detail);
    case Status::Cancelled:
        return withDetail(ReplyText::tr("cancelled"), detail);
    case Status::NotConnected:
        return withDetail(ReplyText::tr("not connected to a drive"), detail);
    case Status::Unsupported:
        return withDetail(ReplyText::tr("this request cannot be sent"), detail);
    case Status::NoReply:
        return ReplyText::tr("sent to a group of drives or to all drives, which never answer: "
                             "carried out, not confirmed");
    case Status::DriveSilent:
        return detail.isEmpty() ? ReplyText::tr("the drive stopped answering")
                                : ReplyText::tr("the drive stopped answering: %1").arg(detail);
    }
    return statusName(status);
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
    case Reply::Status::DriveSilent: return QStringLiteral("drive silent");
    }
    return QStringLiteral("status %1").arg(int(status));
}

} // namespace DriveDesk
