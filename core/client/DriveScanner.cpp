#include "DriveScanner.h"

#include "parameters/MetadataCache.h"
#include "parameters/ParameterList.h"

#include <QPointer>

#include <algorithm>
#include <type_traits>

namespace DriveDesk {

namespace {

// Service 13 function 1: the device identification text.
constexpr quint8 kIdentifyFunction = 1;

} // namespace

DriveScanner::DriveScanner(RequestSink &sink, ScanOptions options, Language language,
                           QObject *parent)
    : QObject(parent)
    , m_sink(sink)
    , m_options(std::move(options))
    , m_language(language)
{}

DriveScanner::~DriveScanner() = default;

void DriveScanner::start()
{
    if (m_started || m_finished)
        return;
    m_started = true;
    m_lineErrorsAtStart = m_sink.lineErrors();

    // Service 13 is DriveDesk's extension: seed 000 has none (over HSP5 a drive could not
    // even frame it) and seed 003 marks it reserved. It is sent only where the user said the
    // drive has it; a drive without the function refuses it (ack 7): no text then.
    if (m_options.identificationText && m_sink.supports(Service::Fieldbus, Access::Read)) {
        enqueue(Service::Fieldbus, FieldbusData{kIdentifyFunction, 0, 0, {}},
                tr("identification"), [this](const Reply &reply) {
                    if (const auto *data = reply.data<FieldbusData>())
                        m_state.identification = driveText(data->data);
                    else if (!reply.isAnswer())
                        m_warnings.append(failure(tr("identification"), reply));
                });
    }
    if (!probeCache())
        scanGroups();
    submitQueued();
}

void DriveScanner::scanGroups()
{
    QList<quint8> pages = m_options.groupPages;
    if (pages.isEmpty()) {
        for (int page = 0; page <= 0xFF; ++page)
            pages.append(quint8(page));
    }
    std::sort(pages.begin(), pages.end());
    pages.erase(std::unique(pages.begin(), pages.end()), pages.end());
    for (quint8 page : std::as_const(pages))
        probeGroup(page);
}

void DriveScanner::cancel()
{
    if (m_finished)
        return;
    // Finished first: the Cancelled replies the sink now delivers find nothing left to do.
    m_finished = true;
    // A stopped scan never asks again: what waited for its second round keeps its failure.
    deliverUnsettled();
    m_queue.clear();
    m_sink.cancelPending();
    emit finished(result(tr("cancelled")));
}

void DriveScanner::enqueue(Service service, ServiceData data, QString what, Handler handle,
                           Check check)
{
    switch (service) {
    case Service::Properties:
        ++m_values.asked;
        break;
    case Service::ParameterValue:
    case Service::ParameterValueStandard:
        ++m_values.reads;
        break;
    case Service::PlaintextIndices:
        ++m_plaintexts.asked;
        break;
    case Service::PlaintextDefinition:
    case Service::CombivisPlaintext:
        ++m_plaintexts.reads;
        break;
    default:
        break;
    }
    auto request = std::make_shared<QueuedRequest>();
    request->telegram = Telegram::request(service, Access::Read, std::move(data));
    request->what = std::move(what);
    request->handle = std::move(handle);
    request->check = std::move(check);
    m_queue.push_back(std::move(request));
    ++m_enqueued;
}

template<typename T>
void DriveScanner::readParameter(quint8 page, quint8 number, Service service, ServiceData data,
                                 const QString &label,
                                 std::function<void(ScanParameter &, const T &)> apply)
{
    Check check;
    if constexpr (std::is_same_v<T, ParameterValue> || std::is_same_v<T, DefaultValue>)
        check = [this, page, number](const Reply &reply) {
            return implausibleRead(page, number, reply);
        };
    enqueue(service, std::move(data), parameterWhat(page, number, label),
            [this, page, number, label, apply = std::move(apply)](const Reply &reply) {
                ScanParameter &parameter = m_state.parameter(page, number);
                if (const T *answer = reply.data<T>()) {
                    apply(parameter, *answer);
                    return;
                }
                if constexpr (std::is_same_v<T, ParameterValue>) {
                    failValue(parameter, label, reply);
                } else {
                    fail(parameter, label, reply);
                    ++parameter.metadataErrors;
                }
            },
            std::move(check));
}

// ScanValues.cpp reads values through it.
template void DriveScanner::readParameter<ParameterValue>(
    quint8, quint8, Service, ServiceData, const QString &,
    std::function<void(ScanParameter &, const ParameterValue &)>);

void DriveScanner::submitQueued()
{
    if (m_submitting)
        return;
    m_submitting = true;
    const QPointer<DriveScanner> self(this);
    checkLine();
    while (!m_finished && m_submitted < kJobRequestWindow && !m_queue.empty()) {
        Queued next = std::move(m_queue.front());
        m_queue.pop_front();
        ++m_submitted;
        ++next->reads;
        m_sink.submit(next->telegram, [self, next](const Reply &reply) {
            if (self)
                self->onReplied(reply, next);
        });
        if (!self)
            return;
    }
    m_submitting = false;
    if (!m_finished && m_queue.empty() && m_submitted == 0) {
        if (startSecondRound())
            return submitQueued();
        finish({});
    }
}

void DriveScanner::onReplied(const Reply &reply, const Queued &request)
{
    --m_submitted;
    ++m_done;
    if (m_finished)
        return;
    switch (reply.status) {
    case Reply::Status::Cancelled:
        finish(tr("cancelled"));
        return;
    case Reply::Status::LinkLost:
    case Reply::Status::NotConnected:
    case Reply::Status::DriveSilent:
        finish(reply.message());
        return;
    default:
        break;
    }
    checkLine();
    settle(request, reply);
    emit progress(m_done, total(), request->what);
    submitQueued();
}

void DriveScanner::finish(const QString &reason)
{
    m_finished = true;
    // A stopped scan never asks again: what waited for its second round keeps its failure.
    deliverUnsettled();
    m_queue.clear();
    // A scan that stops keeps the texts read so far.
    deliverUnfinishedPlaintexts();
    m_state.rejectImplausibleValues();
    // Stored with every value read: the identity is in the values of its parameters.
    if (reason.isEmpty() && mayStore()) {
        // A group that came up short is no picture of the kind either.
        const DriveDescription complete = m_state.describe(m_language, {});
        if (complete.incompleteReason.isEmpty())
            store(complete);
    }
    emit finished(result(reason));
}

DriveDescription DriveScanner::result(const QString &reason)
{
    DriveDescription drive = m_state.describe(m_language, reason);
    drive.metadataFromCache = m_cachedKind.has_value();
    drive.warnings = m_warnings;
    if (!m_options.values) {
        // The identification values were read for the identity only.
        for (GroupDescription &group : drive.groups) {
            for (ParameterDescription &parameter : group.parameters)
                parameter.values.fill(std::nullopt);
        }
    }
    if (m_options.parameterList)
        return ParameterList::fromScan(drive);
    return drive;
}

int DriveScanner::total() const
{
    // What is enqueued, plus an estimate of what is still to come: a parameter still to be
    // named costs its name, a name on its way services 2, 3, 4, 5 (and 7); the answer to its properties leads
    // to its value reads (one, or one per set), the answer to its plaintext indices to the
    // plaintext tables not read yet. Those follow-ups are estimated from the answers so far,
    // so that the bar follows the telegrams instead of racing ahead and stalling.
    const double values = m_options.values ? m_values.perAnswer(1.0) : 0.0;
    const double plaintexts = m_options.plaintexts ? m_plaintexts.perAnswer(1.0) : 0.0;
    const double afterName = 4 + (m_options.plaintexts ? 1 : 0) + values + plaintexts;
    double expected = 0;
    for (const auto &[page, group] : m_state.groups)
        expected += group.namesToAsk() * (1 + afterName) + group.namesPending * afterName;
    expected += (m_values.asked - m_values.answered) * values;
    expected += (m_plaintexts.asked - m_plaintexts.answered) * plaintexts;
    return m_enqueued + int(expected);
}

void DriveScanner::readLimits(quint8 page, quint8 number)
{
    const quint16 address = m_state.parameter(page, number).description.address;
    readParameter<ParameterLimits>(page, number, Service::Limits, ParameterLimits{address},
                                   tr("limits"), [](ScanParameter &p, const ParameterLimits &d) {
                                       p.description.minimum = d.lower;
                                       p.description.maximum = d.upper;
                                       p.limitsKnown = true;
                                   });
}

void DriveScanner::readDefault(quint8 page, quint8 number)
{
    const quint16 address = m_state.parameter(page, number).description.address;
    readParameter<DefaultValue>(page, number, Service::DefaultValue, DefaultValue{address},
                                tr("default value"), [](ScanParameter &p, const DefaultValue &d) {
                                    p.description.defaultValue = d.value;
                                    p.defaultKnown = true;
                                });
}

void DriveScanner::readScaling(quint8 page, quint8 number)
{
    const quint16 address = m_state.parameter(page, number).description.address;
    readParameter<DisplayScalingData>(page, number, Service::DisplayScaling,
                                      DisplayScalingData{address}, tr("display scaling"),
                                      [address](ScanParameter &p, const DisplayScalingData &d) {
                                          p.description.scaling = d;
                                          p.description.scaling.address = address;
                                      });
}

void DriveScanner::readMetadata(quint8 page, quint8 number)
{
    const quint16 address = m_state.parameter(page, number).description.address;
    readLimits(page, number);
    readDefault(page, number);
    enqueue(Service::Properties, PropertiesData{address},
            parameterWhat(page, number, tr("properties")),
            [this, page, number](const Reply &reply) {
                ScanParameter &p = m_state.parameter(page, number);
                const auto *d = reply.data<PropertiesData>();
                if (!d) {
                    fail(p, tr("properties"), reply);
                    ++p.metadataErrors;
                    // Without bit 11 it is unknown whether the value is one or one per set.
                    if (m_options.values)
                        p.errors.append(tr("values: not read, the properties are unknown"));
                    return;
                }
                p.description.properties1 = d->properties1;
                p.description.properties2 = d->properties2;
                if (wantsValue(page, number))
                    readValues(page, number, p.description.isSetProgrammable());
            });
    readScaling(page, number);
    if (!m_options.plaintexts)
        return;
    readParameter<PlaintextIndicesData>(
        page, number, Service::PlaintextIndices, PlaintextIndicesData{address},
        tr("plaintext indices"),
        [this, page, number, address](ScanParameter &p, const PlaintextIndicesData &d) {
            p.description.plaintextIndices = d;
            p.description.plaintextIndices.address = address;
            readPlaintexts(page, number, d);
        });
}

QString DriveScanner::parameterWhat(quint8 page, quint8 number, const QString &detail) const
{
    const QString &groupId = m_state.groups.at(page).description.id;
    const QString what = tr("group %1: parameter %2").arg(groupId, parameterId(groupId, number));
    return detail.isEmpty() ? what : QStringLiteral("%1, %2").arg(what, detail);
}

QString DriveScanner::failure(const QString &label, const Reply &reply) const
{
    // An Ok reply without the expected payload is a decoding fault, not the drive's word.
    const QString service = serviceName(reply.request.service);
    const QString reason
        = reply.ok() ? tr("the answer carries no %1").arg(service) : reply.message();
    return QStringLiteral("%1: %2").arg(label, reason);
}

} // namespace DriveDesk
