#include "CliRunner.h"

#include "bus/LinkFactory.h"
#include "cli/CliJournal.h"
#include "cli/CliPlant.h"
#include "cli/CliSpectrum.h"
#include "cli/ParameterTable.h"
#include "client/WhenFinished.h"
#include "journal/Journal.h"
#include "parameters/DriveIdentity.h"
#include "parameters/MetadataCache.h"
#include "parameters/ParameterCsv.h"
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "parameters/ParameterProperties.h"
#include "scope/ScopeRecording.h"
#include "session/EditJournal.h"
#include "session/PasswordLevelJob.h"
#include "session/ScopeRecorder.h"
#include "state/DriveState.h"
#include "state/ValueEdits.h"

#include <QFutureWatcher>

#include <cstdio>
#include <unistd.h>

namespace DriveDesk {

CliRunner::CliRunner(CliRequest request, QObject *parent)
    : QObject(parent)
    , m_request(std::move(request))
    , m_state(new DriveState(this))
    , m_out(stdout)
    , m_err(stderr)
{}

CliRunner::~CliRunner()
{
    delete m_recorder; // before the recording it writes to
}

void CliRunner::start()
{
    if (m_request.plant) {
        m_plant = new CliPlant(m_request, this);
        connect(m_plant, &CliPlant::finished, this, &CliRunner::finished);
        return m_plant->start();
    }
    if (m_request.command == CliRequest::Command::Journal) {
        QString error;
        const int exitCode = printJournal(m_request, m_out, m_err, &error);
        return exitCode == 0 ? done() : fail(exitCode, error);
    }
    if (m_request.command == CliRequest::Command::Spectrum) { // a file, no drive
        m_finished = true;
        return emit finished(runSpectrumCommand(m_request, m_out, m_err));
    }
    if (!loadFiles())
        return;
    if (m_request.command == CliRequest::Command::Diff
        && !m_request.files.contains(QStringLiteral("drive")))
        return runDiff();
    ClientOptions options;
    options.timeoutMs = m_request.timeoutMs;
    m_client = std::make_unique<DriveClient>(m_request.connection, everyLink(), options);
    connect(m_client.get(), &DriveClient::connected, this, &CliRunner::enterPassword);
    connect(m_client.get(), &DriveClient::baudRateFound, this, [this](qint32 baudRate) {
        if (!m_request.quiet)
            m_err << tr("found the drive at %1 Bd").arg(baudRate) << Qt::endl;
    });
    connect(m_client.get(), &DriveClient::driveStoppedAnswering, this,
            [this](const QString &reason) { m_silence = reason; });
    connect(m_client.get(), &DriveClient::linkLost, this,
            [this](const QString &reason) { m_linkLost = reason; });
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
    whenFinished(m_client->run(job), this, [this](const PasswordLevelOutcome &outcome) {
        if (!outcome.passwordAccepted)
            return fail(1, tr("password not accepted: %1").arg(outcome.error));
        if (!m_request.quiet && outcome.level) {
            m_err << tr("password level in force: %1").arg(passwordLevelName(*outcome.level))
                  << '\n';
        }
        runCommand();
    }, [this] { connectionClosed(); });
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
    case CliRequest::Command::Journal: break; // no drive: start() printed it
    case CliRequest::Command::Spectrum: break; // start() runs it: no drive
    case CliRequest::Command::Revert: runRevert(); break;
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
        whenFinished(m_client->readValueStandard(*address, 0), this, [this, id](const Reply &r) {
            if (!r.ok())
                return fail(1, QStringLiteral("%1: %2").arg(id, r.message()));
            m_out << tr("%1 = %2 (raw)").arg(id).arg(r.data<ParameterValue>()->value) << '\n';
            done();
        }, [this] { connectionClosed(); });
        return;
    }
    bool ok = false;
    const int raw = m_request.value.toInt(&ok, 0);
    if (!ok || raw < -32768 || raw > 65535)
        return fail(2, tr("'%1' is not a raw 16-bit value (DIN66019 writes raw values)").arg(m_request.value));
    // Known by its address alone: no sets, no scaling, written to the active set.
    ParameterDescription parameter;
    parameter.address = *address;
    writeValue(id, parameter, false, raw);
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
        if (!m_silence.isEmpty())
            return fail(1, stoppedAfter(tr("scan"), drive));
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
        scan(one, [this, drive, address = *address, next](const DriveDescription &found) {
            const ParameterDescription *parameter = found.find(address);
            if (!found.incompleteReason.isEmpty())
                return fail(1, found.incompleteReason);
            if (!parameter || found.groups.isEmpty())
                return fail(2, tr("the drive has no parameter %1").arg(m_request.parameter));
            if (!parameter->error.isEmpty())
                return fail(1, QStringLiteral("%1: %2").arg(m_request.parameter, parameter->error));
            // The other groups as the first scan found them (no parameters), for what is read
            // of the drive later (readIdentity).
            DriveDescription known = found;
            for (const GroupDescription &group : drive.groups) {
                if (!known.findGroup(group.id)) {
                    known.groups << group;
                    known.groups.last().parameters.clear();
                }
            }
            m_state->setDescription(known);
            next(found.groups.constFirst(), *parameter);
        });
    });
}

QString CliRunner::valueText(const ParameterDescription &parameter, qint32 raw) const
{
    return ParameterTable::valueText(parameter, raw);
}

QString CliRunner::stoppedAfter(const QString &what, const DriveDescription &drive)
{
    int known = 0;
    int read = 0;
    for (const GroupDescription &group : drive.groups) {
        known += std::max(group.parameterCount, int(group.parameters.size()));
        for (const ParameterDescription &parameter : group.parameters)
            read += parameter.error.isEmpty() && !parameter.name.isEmpty() ? 1 : 0;
    }
    return tr("%1 stopped after %2 of %n parameter(s)", nullptr, known).arg(what).arg(read);
}

void CliRunner::connectionClosed()
{
    fail(3, tr("the connection to the drive was closed"));
}

void CliRunner::fail(int exitCode, const QString &message)
{
    if (m_finished)
        return;
    m_finished = true;
    m_out.flush();
    QString text = message;
    const bool silent = m_client && (!m_silence.isEmpty() || m_client->isDriveSilent());
    if (silent && (exitCode == 1 || exitCode == 3)) {
        exitCode = 3;
        const QString reason = m_silence.isEmpty() ? tr("no answer") : m_silence;
        if (!message.contains(QLatin1String("stopped answering")))
            text = tr("the drive stopped answering (%1): %2").arg(reason, message);
    } else if (!m_linkLost.isEmpty() && exitCode == 1) {
        // The work could not be finished because the line went: no connection (exit 3).
        exitCode = 3;
        text = tr("the connection to the drive was lost (%1): %2").arg(m_linkLost, message);
    }
    m_err << QStringLiteral("drivedesk-cli: ") << text << Qt::endl;
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
