#include "ReplyCheck.h"

#include "parameters/DisplayScaling.h"
#include "parameters/ParameterFormat.h"

#include <QCoreApplication>

#include <optional>

namespace DriveDesk {

namespace {

bool isDuplex(Service service)
{
    return int(service) >= int(Service::ProcessDataDuplex1)
           && int(service) <= int(Service::ProcessDataDuplex6);
}

bool isDefaultCheck(Service service)
{
    return service == Service::CheckDefault || service == Service::CheckDefaultStandard;
}

// The parameter or group address a payload names, for the payloads that have one.
std::optional<quint16> addressOf(const ServiceData &data)
{
    return std::visit(
        [](const auto &d) -> std::optional<quint16> {
            using T = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<T, ParameterValue> || std::is_same_v<T, ParameterLimits>
                          || std::is_same_v<T, DefaultValue> || std::is_same_v<T, PropertiesData>
                          || std::is_same_v<T, DisplayScalingData> || std::is_same_v<T, NameData>
                          || std::is_same_v<T, PlaintextIndicesData>
                          || std::is_same_v<T, GroupPropertiesData>
                          || std::is_same_v<T, DefaultCheckData>)
                return d.address;
            else
                return std::nullopt;
        },
        data);
}

QString hex4(quint16 value)
{
    return QStringLiteral("%1h").arg(value, 4, 16, QLatin1Char('0')).toUpper().replace(
        QLatin1Char('H'), QLatin1Char('h'));
}

QString accessName(Access access)
{
    return access == Access::Write ? QStringLiteral("write") : QStringLiteral("read");
}

// Copies the fields only the request carries into the answer's payload of the same type.
void fillRequestFields(const ServiceData &sent, ServiceData &answer)
{
    std::visit(
        [&sent](auto &a) {
            using T = std::decay_t<decltype(a)>;
            const T *s = std::get_if<T>(&sent);
            if (!s)
                return;
            if constexpr (std::is_same_v<T, ParameterValue>
                          || std::is_same_v<T, DefaultCheckData>) {
                a.address = s->address;
                a.set = s->set;
            } else if constexpr (std::is_same_v<T, NameData>) {
                a.address = s->address;
                a.language = s->language;
            } else if constexpr (std::is_same_v<T, DisplayPlaintextData>) {
                a.index = s->index;
                a.subindex = s->subindex;
                a.language = s->language;
            } else if constexpr (std::is_same_v<T, CombivisPlaintextData>) {
                a.index = s->index;
                a.definition = s->definition;
                a.subindex = s->subindex;
                a.language = s->language;
            } else if constexpr (std::is_same_v<T, PlaintextDefinitionData>) {
                a.index = s->index;
                a.definition = s->definition;
                a.language = s->language;
            } else if constexpr (std::is_same_v<T, FieldbusData>) {
                a.function = s->function;
                a.index = s->index;
                a.subindex = s->subindex;
            } else if constexpr (std::is_same_v<T, ScopeRecordData>) {
                a.mode = s->mode;
                a.index = s->index;
            } else if constexpr (std::is_same_v<T, ProcessParameterData>) {
                a.parameterAddress = s->parameterAddress;
            } else if constexpr (std::is_same_v<T, ParameterLimits>
                                 || std::is_same_v<T, DefaultValue>
                                 || std::is_same_v<T, PropertiesData>
                                 || std::is_same_v<T, DisplayScalingData>
                                 || std::is_same_v<T, PlaintextIndicesData>
                                 || std::is_same_v<T, GroupPropertiesData>) {
                a.address = s->address;
            }
        },
        answer);
}

// The translation context of the plausibility messages: the checks are free functions.
class ReplyCheckText
{
    Q_DECLARE_TR_FUNCTIONS(ReplyCheck)
};

// A drive text holds printable Latin-1 up to its first NUL; what follows the NUL is padding.
QString controlCharacter(const QByteArray &text)
{
    for (const char c : text) {
        const auto code = quint8(c);
        if (code == 0)
            return {};
        if (code < 0x20 || (code >= 0x7F && code < 0xA0))
            return ReplyCheckText::tr("a text with the control character %1h")
                .arg(code, 2, 16, QLatin1Char('0'))
                .toUpper()
                .replace(QLatin1Char('H'), QLatin1Char('h'));
    }
    return {};
}

} // namespace

QString implausibleAnswer(const Telegram &answer)
{
    return std::visit(
        [](const auto &d) -> QString {
            using T = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<T, NameData> || std::is_same_v<T, CombivisPlaintextData>
                          || std::is_same_v<T, PlaintextDefinitionData>) {
                return controlCharacter(d.text);
            } else if constexpr (std::is_same_v<T, ParameterLimits>) {
                if (d.lower > d.upper)
                    return ReplyCheckText::tr("limits %1 .. %2: the minimum lies above the maximum")
                        .arg(d.lower)
                        .arg(d.upper);
            } else if constexpr (std::is_same_v<T, DisplayScalingData>) {
                const QString invalid = DisplayScaling(d).invalidReason();
                if (!invalid.isEmpty())
                    return ReplyCheckText::tr("a display scaling that cannot be computed (%1)")
                        .arg(invalid);
            } else if constexpr (std::is_same_v<T, GroupPropertiesData>) {
                if (int(d.countMinusOne) > int(d.highestNumber))
                    return ReplyCheckText::tr("a group of %1 parameters numbered 0 to %2")
                        .arg(int(d.countMinusOne) + 1)
                        .arg(d.highestNumber);
                return controlCharacter(QByteArray(d.id.data(), int(d.id.size())));
            }
            return {};
        },
        answer.data);
}

QString implausibleValue(const ParameterDescription &parameter, qint32 value)
{
    const ParameterFormat format(parameter);
    if (format.isWithinLimits(value))
        return {};
    return ReplyCheckText::tr("%1 lies outside the limits %2 .. %3")
        .arg(value)
        .arg(parameter.minimum)
        .arg(parameter.maximum);
}

bool carriesInvokeId(Protocol protocol, Service service)
{
    if (protocol == Protocol::Hsp5)
        return true;
    return service != Service::Legacy && service != Service::StatusInterrogation;
}

QString replyMismatch(Protocol protocol, const Telegram &sent, const Telegram &answer)
{
    if (!answer.isResponse())
        return QStringLiteral("a request, not an answer");
    const bool byInvokeId = carriesInvokeId(protocol, sent.service);
    if (byInvokeId && answer.operatorInvoke != sent.operatorInvoke) {
        return QStringLiteral("invoke id %1, expected %2")
            .arg(answer.operatorInvoke)
            .arg(sent.operatorInvoke);
    }
    if (protocol == Protocol::Hsp5 && answer.inverterInvoke != 0)
        return QStringLiteral("answer to an inverter cycle %1").arg(answer.inverterInvoke);

    // DIN66019(II) short answers (IID ACK, IID code NAK/EOT) name no service.
    if (answer.service == Service::Unspecified) {
        if (protocol == Protocol::Hsp5)
            return QStringLiteral("an answer without service");
        const bool mayBeAcknowledged = sent.isWrite() || isDefaultCheck(sent.service)
                                       || sent.service == Service::StatusInterrogation;
        if (answer.ack == Ack::Ok && !mayBeAcknowledged) {
            return QStringLiteral("a bare acknowledge to a read of %1, which must carry data")
                .arg(serviceName(sent.service));
        }
        return {};
    }

    if (answer.service != sent.service) {
        return QStringLiteral("answer of service %1 (%2) to a request of service %3 (%4)")
            .arg(int(answer.service))
            .arg(serviceName(answer.service))
            .arg(int(sent.service))
            .arg(serviceName(sent.service));
    }
    if (protocol == Protocol::Hsp5) {
        if (answer.access != sent.access) {
            return QStringLiteral("%1 answer to a %2 request")
                .arg(accessName(answer.access), accessName(sent.access));
        }
    } else if (sent.isWrite() && !isDuplex(sent.service) && sent.service != Service::Legacy) {
        return QStringLiteral("data answer to a write of %1").arg(serviceName(sent.service));
    }

    // A read's data must be the service's payload; writes may come back without one.
    const bool carriesData = !sent.isWrite() || isDuplex(sent.service);
    if (carriesData && answer.ack == Ack::Ok && answer.data.index() != sent.data.index())
        return QStringLiteral("payload of the wrong type for %1").arg(serviceName(sent.service));

    const std::optional<quint16> sentAddress = addressOf(sent.data);
    const std::optional<quint16> answerAddress = addressOf(answer.data);
    if (sentAddress && answerAddress && answer.data.index() == sent.data.index()) {
        // Only the legacy DIN66019 answer carries the address on the wire; other decoders
        // leave it 0, which says nothing.
        const bool carried = sent.service == Service::Legacy || *answerAddress != 0;
        if (carried && *answerAddress != *sentAddress) {
            return QStringLiteral("answer for address %1, expected %2")
                .arg(hex4(*answerAddress), hex4(*sentAddress));
        }
    }
    return {};
}

Telegram completeAnswer(const Telegram &sent, const Telegram &answer)
{
    Telegram complete = answer;
    complete.service = sent.service;
    complete.access = sent.access;
    complete.direction = Direction::Response;
    if ((sent.isWrite() && !isDuplex(sent.service))
        || std::holds_alternative<std::monostate>(answer.data))
        complete.data = sent.data; // an acknowledge: what was asked for is what holds
    else if (answer.data.index() == sent.data.index())
        fillRequestFields(sent.data, complete.data);
    return complete;
}

} // namespace DriveDesk
