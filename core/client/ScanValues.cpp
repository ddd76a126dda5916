// How a scan reads values: a set-programmable value over all sets at once, split only where
// the drive says the sets differ.
#include "DriveScanner.h"

#include "parameters/ParameterList.h"

#include <bit>

namespace DriveDesk {

namespace {

constexpr quint8 kAllSets = 0xFF;

// "0", "0-7", "0, 2, 5": the sets of a mask for a user.
QString setList(quint8 mask)
{
    QStringList sets;
    for (int set = 0; set < kParameterSets; ++set) {
        if (mask & (1u << set))
            sets.append(QString::number(set));
    }
    const int first = std::countr_zero(unsigned(mask));
    const int last = 31 - std::countl_zero(unsigned(mask));
    if (sets.size() > 2 && last - first + 1 == sets.size())
        return QStringLiteral("%1-%2").arg(first).arg(last);
    return sets.join(QStringLiteral(", "));
}

// The lower and upper half of the sets in a mask: FFh gives 0Fh and F0h.
std::pair<quint8, quint8> halves(quint8 mask)
{
    const int keep = std::popcount(unsigned(mask)) / 2;
    quint8 lower = 0;
    for (int set = 0, taken = 0; set < kParameterSets && taken < keep; ++set) {
        if (mask & (1u << set)) {
            lower |= quint8(1u << set);
            ++taken;
        }
    }
    return {lower, quint8(mask & ~lower)};
}

} // namespace

bool DriveScanner::wantsValue(quint8 page, quint8 number) const
{
    const ScanParameter &scanned = m_state.groups.at(page).parameters.at(number);
    if (m_options.parameterList && !ParameterList::isReadByUpload(scanned.description))
        return false;
    if (m_options.values)
        return true;
    // The identification parameters are read for the drive's identity (and the cache's key).
    const QString &group = m_state.groups.at(page).description.id;
    for (const IdentificationParameter &id : DriveIdentity::parameters()) {
        if (group == QLatin1String(id.group) && number == id.number)
            return true;
    }
    return false;
}

void DriveScanner::readValues(quint8 page, quint8 number, bool setProgrammable)
{
    const quint16 address = m_state.parameter(page, number).description.address;
    if (!setProgrammable) {
        readParameter<ParameterValue>(page, number, Service::ParameterValueStandard,
                                      ParameterValue{address, 0, 0}, tr("value"),
                                      [](ScanParameter &p, const ParameterValue &d) {
                                          p.description.values[0] = d.value;
                                      });
        m_queue.back()->valueOf = std::pair{page, number};
        return;
    }
    readSetValues(page, number, kAllSets);
}

void DriveScanner::readSetValues(quint8 page, quint8 number, quint8 setMask)
{
    const quint16 address = m_state.parameter(page, number).description.address;
    const bool single = std::popcount(unsigned(setMask)) == 1;
    const QString label = single ? tr("value of set %1").arg(setList(setMask))
                                 : tr("values of sets %1").arg(setList(setMask));
    enqueue(Service::ParameterValue, ParameterValue{address, setMask, 0},
            parameterWhat(page, number, label),
            [this, page, number, setMask, single, label](const Reply &reply) {
                ScanParameter &parameter = m_state.parameter(page, number);
                if (const auto *read = reply.data<ParameterValue>()) {
                    for (int set = 0; set < kParameterSets; ++set) {
                        if (setMask & (1u << set))
                            parameter.description.values[set] = read->value;
                    }
                    return;
                }
                // Ack 3 to a read over several sets: their values differ (seed 000, 2.1). A
                // drive with fewer sets refuses the mask (ack 11): its sets answer one by one.
                if (!single && reply.status == Reply::Status::Refused
                    && (reply.ack() == Ack::DataInvalid || reply.ack() == Ack::SetInvalid)) {
                    const auto [lower, upper] = halves(setMask);
                    readSetValues(page, number, lower);
                    readSetValues(page, number, upper);
                    return;
                }
                failValue(parameter, label, reply);
            },
            [this, page, number](const Reply &reply) {
                return implausibleRead(page, number, reply);
            });
    m_queue.back()->valueOf = std::pair{page, number};
}

void DriveScanner::failValue(ScanParameter &parameter, const QString &label,
                             const Reply &reply) const
{
    const ParameterProperties properties(parameter.description.properties1,
                                         parameter.description.properties2);
    if (!reply.disagreed || !properties.isChangedByInverter())
        return fail(parameter, label, reply);
    parameter.errors.append(tr("%1: not confirmed: the drive changes it by itself, and on a line "
                               "with errors no two reads agreed")
                                .arg(label));
}

} // namespace DriveDesk
