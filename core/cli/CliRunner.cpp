#include "CliRunner.h"

#include "bus/LinkFactory.h"
#include "cli/ParameterTable.h"
#include "parameters/DriveIdentity.h"
#include "parameters/MetadataCache.h"
#include "parameters/ParameterCsv.h"
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "parameters/ParameterProperties.h"
#include "session/ScopeRecorder.h"
#include "scope/ScopeRecording.h"
#include "session/PasswordLevelJob.h"
#include "session/ValueChange.h"

#include <QFutureWatcher>

#include <cstdio>
#include <unistd.h>

namespace DriveDesk {

QString CliRunner::setListText(quint8 mask)
{
    if (mask == 0xFF)
        return tr("all sets");
    QStringList sets;
    for (int s = 0; s < kParameterSets; ++s) {
        if (mask & (1u << s))
            sets << QString::number(s);
    }
    const int count = int(sets.size());
    return tr("set(s) %1", nullptr, count).arg(sets.join(QLatin1Char(',')));
}

CliRunner::CliRunner(CliRequest request, QObject *parent)
    : QObject(parent)
    , m_request(std::move(request))
    , m_out(stdout)
    , m_err(stderr)
{}

CliRunner::~CliRunner()
{
    delete m_recorder; // before the recording it writes to
}

void CliRunner::start()
{
    if (!loadFiles())
        return;
    if (m_request.command == CliRequest::Command::Diff
        && !m_request.files.contains(QStringLiteral("drive")))
        return runDiff();
    ClientOptions options;
    options.timeoutMs = m_request.timeoutMs;
    m_client = std::make_unique<DriveClient>(m_request.connection, everyLink(), options);
    connect(m_client.get(), &DriveClient::connected, this, &CliRunner::enterPassword);
    connect(m_client.get(), &DriveClient::connectionFailed, this, [this](const QString &reason) {
        fail(3, tr("cannot connect to %1: %2")
                    .arg(m_request.connection.displayName(), reason));
    });
    m_client->connectToDrive();
}

// The window's password dialog does the same: core's PasswordLevelJob writes ud.01 and reads
// the level the drive then has in force.
void CliRunner::enterPassword()
{
    if (!m_request.password)
        return runCommand();
    const auto job = std::make_shared<PasswordLevelJob>(m_request.connection.protocol,
                                                        m_request.password);
    m_client->run(job).then(this, [this](const PasswordLevelOutcome &outcome) {
        if (!outcome.passwordAccepted)
            return fail(1, tr("password not accepted: %1").arg(outcome.error));
        if (!m_request.quiet && outcome.level) {
            m_err << tr("password level in force: %1").arg(passwordLevelName(*outcome.level))
                  << '\n';
        }
        runCommand();
    });
}

void CliRunner::runCommand()
{
    if (m_request.connection.protocol == Protocol::Din66019)
        return runLegacy();
    switch (m_request.command) {
    case CliRequest::Command::Info: runInfo(); break;
    case CliRequest::Command::Scan: runScan(); break;
    case CliRequest::Command::Read: runRead(); break;
    case CliRequest::Command::Write: runWrite(); break;
    case CliRequest::Command::Diff: runDiff(); break;
    case CliRequest::Command::Upload: runUpload(); break;
    case CliRequest::Command::Download: runDownload(); break;
    case CliRequest::Command::Scope: runScope(); break;
    }
}

// DIN66019 reads and writes values by address and nothing else: no names, limits or scaling.
void CliRunner::runLegacy()
{
    if (m_request.command != CliRequest::Command::Read
        && m_request.command != CliRequest::Command::Write) {
        return fail(2, tr("DIN66019 carries parameter values only; use --protocol din66019ii "
                          "for anything but read and write"));
    }
    QString error;
    const auto address = ParameterId::parse(m_request.parameter, QList<GroupAddress>{}, &error);
    if (!address) {
        return fail(2, tr("%1 (DIN66019 has no group names: give the address, e.g. 0x0203)")
                           .arg(error));
    }
    const QString id = ParameterId::hexAddress(*address);
    if (m_request.command == CliRequest::Command::Read) {
        m_client->readValueStandard(*address, 0).then(this, [this, id](const Reply &r) {
            if (!r.ok())
                return fail(1, QStringLiteral("%1: %2").arg(id, r.message()));
            m_out << tr("%1 = %2 (raw)").arg(id).arg(r.data<ParameterValue>()->value) << '\n';
            done();
        });
        return;
    }
    bool ok = false;
    const int raw = m_request.value.toInt(&ok, 0);
    if (!ok || raw < -32768 || raw > 65535)
        return fail(2, tr("'%1' is not a raw 16-bit value (DIN66019 writes raw values)").arg(m_request.value));
    m_client->writeValueStandard(*address, raw, 0).then(this, [this, id, address = *address](const Reply &r) {
        if (!r.ok())
            return fail(1, QStringLiteral("%1: %2").arg(id, r.message()));
        m_client->readValueStandard(address, 0).then(this, [this, id](const Reply &back) {
            if (!back.ok())
                return fail(1, tr("%1: written, but reading it back failed: %2")
                                   .arg(id, back.message()));
            m_out << tr("%1 = %2 (raw)").arg(id).arg(back.data<ParameterValue>()->value) << '\n';
            done();
        });
    });
}

void CliRunner::scan(ScanOptions options, std::function<void(const DriveDescription &)> next)
{
    options.metadata = m_request.useCache ? MetadataSource::Cache : MetadataSource::RefreshCache;
    auto *watcher = new QFutureWatcher<DriveDescription>(this);
    connect(watcher, &QFutureWatcher<DriveDescription>::progressTextChanged, this,
            [this, watcher](const QString &text) {
                progressLine(watcher->progressValue() * 100 / std::max(1, watcher->progressMaximum()),
                             text);
            });
    connect(watcher, &QFutureWatcher<DriveDescription>::finished, this,
            [this, watcher, options, next = std::move(next)] {
                progressLine(-1, {});
                const DriveDescription description = watcher->future().result();
                watcher->deleteLater();
                noteScan(description, options.cacheDirectory);
                next(description);
            });
    watcher->setFuture(m_client->scan(options));
}

void CliRunner::noteScan(const DriveDescription &drive, const QString &cacheDirectory)
{
    for (const QString &warning : drive.warnings)
        m_err << warning << '\n';
    if (drive.metadataFromCache && !m_request.quiet && !m_cacheNoted) {
        m_cacheNoted = true; // once, however many scans a command makes
        m_err << tr("metadata from the cache of this kind of drive (%1); "
                    "--no-cache reads it from the drive")
                     .arg(cacheDirectory.isEmpty() ? MetadataCache::defaultDirectory()
                                                   : cacheDirectory)
              << '\n';
    }
}

void CliRunner::runInfo()
{
    ScanOptions groupsOnly;
    groupsOnly.parameters = false;
    groupsOnly.values = false;
    groupsOnly.plaintexts = false;
    scan(groupsOnly, [this](const DriveDescription &drive) {
        if (!drive.incompleteReason.isEmpty())
            return fail(1, tr("could not read the groups: %1").arg(drive.incompleteReason));
        // Then the groups that hold the identification parameters, with their values.
        ScanOptions system;
        for (const GroupDescription &group : drive.groups) {
            for (const IdentificationParameter &id : DriveIdentity::parameters()) {
                if (group.id == QLatin1String(id.group)) {
                    system.groupPages.append(quint8(group.address >> 8));
                    break;
                }
            }
        }
        if (system.groupPages.isEmpty()) {
            m_out << ParameterTable::info(drive, {});
            return done();
        }
        scan(system, [this, drive](const DriveDescription &systemGroup) {
            m_out << ParameterTable::info(drive, systemGroup);
            if (!systemGroup.incompleteReason.isEmpty())
                return fail(1, systemGroup.incompleteReason);
            done();
        });
    });
}

void CliRunner::runScan()
{
    ScanOptions options;
    options.values = m_request.values;
    scan(options, [this](const DriveDescription &drive) {
        if (m_request.format == CliRequest::Format::Json)
            m_out << QString::fromUtf8(ParameterDocument::toJson(drive));
        else if (m_request.format == CliRequest::Format::Csv)
            m_out << QString::fromUtf8(parametersAsCsv(drive));
        else
            m_out << ParameterTable::scan(drive, m_request.values);
        m_out.flush();
        if (!drive.incompleteReason.isEmpty())
            return fail(1, tr("scan incomplete: %1").arg(drive.incompleteReason));
        done();
    });
}

void CliRunner::lookUpParameter(
    std::function<void(const GroupDescription &, const ParameterDescription &)> next)
{
    ScanOptions groupsOnly;
    groupsOnly.parameters = false;
    scan(groupsOnly, [this, next = std::move(next)](const DriveDescription &drive) {
        if (!drive.incompleteReason.isEmpty())
            return fail(1, tr("could not read the groups: %1").arg(drive.incompleteReason));
        QString error;
        const auto address = ParameterId::parse(m_request.parameter, drive, &error);
        if (!address)
            return fail(2, error);
        ScanOptions one;
        one.groupPages = {quint8(*address >> 8)};
        one.onlyParameters = {*address};
        one.values = false;
        scan(one, [this, address = *address, next](const DriveDescription &found) {
            const ParameterDescription *parameter = found.find(address);
            if (!found.incompleteReason.isEmpty())
                return fail(1, found.incompleteReason);
            if (!parameter || found.groups.isEmpty())
                return fail(2, tr("the drive has no parameter %1").arg(m_request.parameter));
            if (!parameter->error.isEmpty())
                return fail(1, QStringLiteral("%1: %2").arg(m_request.parameter, parameter->error));
            next(found.groups.constFirst(), *parameter);
        });
    });
}

void CliRunner::runRead()
{
    lookUpParameter([this](const GroupDescription &group, const ParameterDescription &parameter) {
        const QString id = parameterId(group.id, parameter.number());
        QFuture<Reply> reply = m_request.set
                                   ? m_client->readValue(parameter.address, quint8(1u << *m_request.set))
                                   : m_client->readValueStandard(parameter.address, 0);
        const QString where = m_request.set ? tr("set %1").arg(*m_request.set) : tr("active set");
        reply.then(this, [this, id, where, parameter](const Reply &r) {
            if (!r.ok())
                return fail(1, QStringLiteral("%1: %2").arg(id, r.message()));
            const qint32 raw = r.data<ParameterValue>()->value;
            m_out << tr("%1  %2 = %3  (raw %4, %5)")
                         .arg(id, parameter.name, valueText(parameter, raw))
                         .arg(raw)
                         .arg(where)
                  << '\n';
            done();
        });
    });
}

void CliRunner::runWrite()
{
    lookUpParameter([this](const GroupDescription &group, const ParameterDescription &parameter) {
        const QString id = parameterId(group.id, parameter.number());
        if (ParameterProperties(parameter.properties1, parameter.properties2).isReadOnly())
            return fail(2, tr("%1 is read-only; nothing was written").arg(id));
        // The window's rule: a plaintext or a number in display units (or a raw integer with
        // --raw), refused when it cannot be held exactly or lies outside the limits.
        const ParameterFormat display(parameter);
        const ParameterFormat format = m_request.raw ? display.rawFormat() : display;
        QString error;
        const std::optional<qint32> raw = format.parse(m_request.value, &error);
        if (!raw)
            return fail(2, tr("%1: %2; nothing was written").arg(id, error));
        ValueChange change;
        change.address = parameter.address;
        change.setProgrammable = parameter.isSetProgrammable();
        change.steps = {WriteStep{m_request.setMask, *raw, false}};
        const auto job = std::make_shared<WriteValueJob>(m_request.connection.protocol, change);
        m_client->run(job).then(this, [this, id, parameter, raw = *raw](const WriteOutcome &outcome) {
            report(id, parameter, raw, outcome);
        });
    });
}

// A write counts only once the drive shows the value: the job read every written set back.
void CliRunner::report(const QString &id, const ParameterDescription &parameter, qint32 raw,
                       const WriteOutcome &outcome)
{
    if (!outcome.anyAcknowledged())
        return fail(1, QStringLiteral("%1: %2").arg(id, outcome.error));
    if (!outcome.readBackError.isEmpty()) {
        return fail(1, tr("%1: written, but reading it back failed: %2")
                           .arg(id, outcome.readBackError));
    }
    QStringList shown;
    QStringList differing;
    for (int set = 0; set < kParameterSets; ++set) {
        const std::optional<qint32> held = outcome.readBack[std::size_t(set)];
        if (!held)
            continue;
        shown << valueText(parameter, *held);
        if (*held != raw) {
            differing << (outcome.activeSetAcknowledged
                              ? tr("the active set holds %1").arg(valueText(parameter, *held))
                              : tr("set %1 holds %2").arg(set).arg(valueText(parameter, *held)));
        }
    }
    shown.removeDuplicates();
    const quint8 mask = outcome.acknowledgedMask;
    m_out << QStringLiteral("%1  %2 = %3  (%4)\n")
                 .arg(id, parameter.name, shown.join(QStringLiteral(" / ")),
                      mask ? setListText(mask) : tr("active set"));
    if (!outcome.error.isEmpty()) {
        return fail(1, tr("%1: not written to %2: %3")
                           .arg(id, setListText(outcome.refusedMask), outcome.error));
    }
    if (!differing.isEmpty()) {
        return fail(1, tr("%1: written %2, but %3")
                           .arg(id, valueText(parameter, raw), differing.join(QStringLiteral(", "))));
    }
    done();
}

QString CliRunner::valueText(const ParameterDescription &parameter, qint32 raw) const
{
    return ParameterTable::valueText(parameter, raw);
}

void CliRunner::fail(int exitCode, const QString &message)
{
    if (m_finished)
        return;
    m_finished = true;
    m_out.flush();
    m_err << QStringLiteral("drivedesk-cli: ") << message << Qt::endl;
    emit finished(exitCode);
}

void CliRunner::done()
{
    if (m_finished)
        return;
    m_finished = true;
    m_out.flush();
    emit finished(0);
}

} // namespace DriveDesk
