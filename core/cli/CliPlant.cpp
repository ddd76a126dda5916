// drivedesk-cli plant: every drive of a plant file found, backed up or checked.
#include "CliPlant.h"

#include "CliFormatOption.h"

#include "cli/CliPlantHistory.h"
#include "history/BackupRepository.h"
#include "history/Git.h"

#include "bus/LinkFactory.h"
#include "link/ConnectionOptions.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

namespace DriveDesk {

std::optional<CliRequest> parsePlantCommand(const QCommandLineParser &parser,
                                            const ConnectionOptions &connection,
                                            const QStringList &positional, QString *error)
{
    if (connection.hasTarget(parser) || connection.hasTargetDetails(parser)) {
        *error = QStringLiteral("plant takes its links from the plant file: --connect, "
                                "--protocol, --address, --baud and --hsp5-extensions do not apply");
        return std::nullopt;
    }
    for (const char *name : {"values", "set", "sets", "raw", "password", "channels", "duration",
                             "rate", "csv", "offline", "channel", "from", "to", "peaks"}) {
        if (parser.isSet(QLatin1String(name))) {
            *error = QStringLiteral("--%1 does not belong to plant").arg(QLatin1String(name));
            return std::nullopt;
        }
    }
    CliRequest request;
    PlantRequest plant;
    const QString action = positional.value(1).toLower();
    const qsizetype expected = action == QLatin1String("find") ? 3 : 4;
    if (action == QLatin1String("find")) {
        plant.action = PlantRequest::Action::Find;
    } else if (action == QLatin1String("backup")) {
        plant.action = PlantRequest::Action::Backup;
    } else if (action == QLatin1String("verify")) {
        plant.action = PlantRequest::Action::Verify;
    } else if (action == QLatin1String("download")) {
        plant.action = PlantRequest::Action::Download;
    } else if (action == QLatin1String("history")) {
        plant.action = PlantRequest::Action::History;
    } else {
        *error = QStringLiteral("plant takes find PLANT, backup PLANT DIR, verify PLANT DIR, "
                                "download PLANT DIR or history PLANT DIR");
        return std::nullopt;
    }
    if (positional.size() != expected) {
        *error = action == QLatin1String("find")
                     ? QStringLiteral("plant find takes a plant file, e.g. plant find line3.json")
                     : QStringLiteral("plant %1 takes a plant file and a directory, e.g. plant %1 "
                                      "line3.json backups")
                           .arg(action);
        return std::nullopt;
    }
    plant.plantFile = positional.value(2);
    plant.directory = positional.value(3);
    plant.update = parser.isSet(QStringLiteral("update"));
    if (plant.update && plant.action != PlantRequest::Action::Find) {
        *error = QStringLiteral("--update belongs to plant find");
        return std::nullopt;
    }
    plant.dryRun = parser.isSet(QStringLiteral("dry-run"));
    plant.force = parser.isSet(QStringLiteral("force"));
    if ((plant.dryRun || plant.force) && plant.action != PlantRequest::Action::Download) {
        *error = QStringLiteral("--dry-run and --force belong to plant download");
        return std::nullopt;
    }
    if (parser.isSet(QStringLiteral("format")) && plant.action != PlantRequest::Action::Verify
        && plant.action != PlantRequest::Action::History) {
        *error = QStringLiteral("--format belongs to plant verify and plant history");
        return std::nullopt;
    }
    if (!parseFormatOption(parser, QStringLiteral("plant"),
                           { QStringLiteral("table"), QStringLiteral("json") }, &request, error))
        return std::nullopt;
    std::optional<Language> language;
    if (!connection.language(parser, &language, error))
        return std::nullopt;
    if (language)
        request.connection.language = *language;
    if (!ConnectionOptions::integer(parser, QCommandLineOption(QStringLiteral("timeout"), {},
                                                               QStringLiteral("ms")),
                                    1, 600000, &request.timeoutMs, error))
        return std::nullopt;
    if (!parsePlantHistoryOptions(parser, plant, error))
        return std::nullopt;
    request.quiet = parser.isSet(QStringLiteral("quiet"));
    request.useCache = !parser.isSet(QStringLiteral("no-cache"));
    request.plant = plant;
    return request;
}

CliPlant::CliPlant(CliRequest request, QObject *parent)
    : QObject(parent)
    , m_request(std::move(request))
    , m_plant(*m_request.plant)
    , m_out(stdout)
    , m_err(stderr)
{}

CliPlant::~CliPlant() = default;

void CliPlant::start()
{
    QString error;
    const std::optional<Plant> plant = PlantFile::load(m_plant.plantFile, &error);
    if (!plant)
        return end(2, error);
    if (m_plant.action == PlantRequest::Action::History) {
        const int exitCode = printPlantHistory(m_request, m_out, &error);
        return end(exitCode, error);
    }
    // Before anything is sent: git missing, or a revision that is not there, is bad input.
    if (m_plant.commit && !Git::isAvailable(&error))
        return end(2, error);
    QString directory = m_plant.directory;
    if (!m_plant.at.isEmpty()) {
        m_revision = extractRevision(m_plant.directory, m_plant.at, &m_revisionId, &error);
        if (!m_revision)
            return end(2, error);
        directory = m_revision->path();
    }
    const PlantRun::Task task = m_plant.action == PlantRequest::Action::Find ? PlantRun::Task::Find
                                : m_plant.action == PlantRequest::Action::Backup
                                    ? PlantRun::Task::Backup
                                : m_plant.action == PlantRequest::Action::Verify
                                    ? PlantRun::Task::Verify
                                    : PlantRun::Task::Download;
    if (task == PlantRun::Task::Backup && !QDir().mkpath(m_plant.directory))
        return end(2, tr("cannot make the directory %1").arg(m_plant.directory));
    if ((task == PlantRun::Task::Verify || task == PlantRun::Task::Download)
        && !QDir(m_plant.directory).exists())
        return end(2, tr("the directory %1 does not exist").arg(m_plant.directory));
    m_run = new PlantRun(*plant, task, directory, everyLink(), this);
    ClientOptions options;
    options.timeoutMs = m_request.timeoutMs;
    m_run->setClientOptions(options);
    ScanOptions reading;
    reading.metadata = m_request.useCache ? MetadataSource::Cache : MetadataSource::RefreshCache;
    m_run->setReading(reading);
    m_run->setLanguage(m_request.connection.language);
    m_run->setDownloadOptions(m_plant.dryRun, m_plant.force);
    if (task == PlantRun::Task::Download && !m_plant.dryRun && m_request.journalWrites) {
        // Before any drive is read: a journal that cannot be written stops every download
        // before anything is written.
        m_journal = std::make_unique<Journal>(m_request.journalPath);
        if (!m_journal->open())
            return end(1, tr("nothing was written: %1 (--no-journal downloads without it)")
                              .arg(m_journal->errorString()));
        m_editJournal = std::make_unique<EditJournal>(
            m_journal.get(), JournalDrive {},
            tr("plant download of %1").arg(QFileInfo(m_plant.plantFile).fileName()));
        m_editJournal->setRemedy(tr("--no-journal downloads without it"));
        m_run->setJournal(m_editJournal.get());
    }
    m_known.openPlant(*plant, directory);
    m_known.follow(m_run);
    connect(m_run, &PlantRun::progress, this, &CliPlant::onProgress);
    connect(m_run, &PlantRun::finished, this, &CliPlant::onFinished, Qt::QueuedConnection);
    m_run->start();
}

bool CliPlant::interrupt()
{
    if (!m_run || !m_run->isRunning() || m_finished)
        return false;
    m_err << tr("stopping every link after the value on its way...") << Qt::endl;
    m_interrupted = true;
    m_run->stop();
    return true;
}

// Lines, not a bar redrawn in place: the links run side by side and their lines interleave.
void CliPlant::onProgress(const QString &link, int address, int percent, const QString &what)
{
    if (m_request.quiet || percent >= 100)
        return;
    const QString name = address < 0 ? link : QStringLiteral("%1-%2").arg(link).arg(address);
    const int step = percent / 25;
    const auto shown = m_shown.constFind(name);
    if (shown != m_shown.cend() && *shown == step && percent != 0)
        return;
    m_shown.insert(name, step);
    m_err << QStringLiteral("%1: [%2%] %3").arg(name).arg(percent, 3).arg(what.isEmpty() ? tr("reading") : what)
          << Qt::endl;
}

void CliPlant::onFinished()
{
    QList<PlantDrive> drives = m_run->drives();
    nameRevisionFiles(drives);
    bool committed = true;
    QString commitError;
    switch (m_plant.action) {
    case PlantRequest::Action::History: break;
    case PlantRequest::Action::Find: printFind(drives); break;
    case PlantRequest::Action::Backup:
        printBackup(drives);
        if (m_plant.commit && !m_interrupted)
            committed = commitAndPrintPlantBackup(m_plant, m_run->plant(), drives, m_out,
                                                  &commitError);
        break;
    case PlantRequest::Action::Verify:
        if (m_request.format == CliRequest::Format::Json)
            printVerifyJson(drives);
        else
            printVerify(drives);
        break;
    case PlantRequest::Action::Download: printDownload(drives); break;
    }
    const bool noneAnswered = m_known.noLinkAnswers();
    const bool allGood = std::all_of(drives.cbegin(), drives.cend(),
                                     [](const PlantDrive &drive) { return drive.isGood(); });
    if (m_plant.action == PlantRequest::Action::Find && m_plant.update && !noneAnswered) {
        QString error;
        if (!PlantFile::save(m_plant.plantFile, m_run->plant(), &error))
            return end(1, error);
        m_out << tr("%1: the addresses found written").arg(m_plant.plantFile) << '\n';
    }
    if (m_interrupted)
        return end(130);
    if (!committed)
        return end(1, commitError);
    if (noneAnswered)
        return end(3, tr("no link answered"));
    end(allGood ? 0 : 1);
}

void CliPlant::nameRevisionFiles(QList<PlantDrive> &drives) const
{
    if (!m_revision)
        return;
    const QString folder = QDir::toNativeSeparators(m_revision->path() + QLatin1Char('/'));
    const QString revision = m_revisionId.left(12) + QLatin1Char(':');
    for (PlantDrive &drive : drives) {
        drive.file = QDir::toNativeSeparators(drive.file).replace(folder, revision);
        drive.reason.replace(folder, revision);
    }
}

void CliPlant::printFind(const QList<PlantDrive> &drives)
{
    for (const PlantDrive &drive : drives) {
        if (drive.outcome == PlantDrive::Outcome::Found) {
            m_out << QStringLiteral("%1: %2").arg(drive.name(),
                                                  drive.identification.isEmpty()
                                                      ? tr("gave no identification")
                                                      : drive.identification)
                  << '\n';
        } else {
            m_out << QStringLiteral("%1: %2: %3")
                         .arg(drive.name(), PlantDrive::outcomeText(drive.outcome), drive.reason)
                  << '\n';
        }
    }
    m_out << PlantDrive::summary(drives, PlantDrive::outcomeText(PlantDrive::Outcome::Found)) << '\n';
}

void CliPlant::printBackup(const QList<PlantDrive> &drives)
{
    for (const PlantDrive &drive : drives) {
        if (drive.outcome == PlantDrive::Outcome::Saved) {
            m_out << tr("%1: saved %2, %n parameter(s)", nullptr, drive.parameters)
                         .arg(drive.name(), QDir::toNativeSeparators(drive.file))
                  << '\n';
        } else {
            m_out << tr("%1: not saved: %2: %3")
                         .arg(drive.name(), PlantDrive::outcomeText(drive.outcome), drive.reason)
                  << '\n';
        }
    }
    m_out << PlantDrive::summary(drives, PlantDrive::outcomeText(PlantDrive::Outcome::Saved)) << '\n';
}

void CliPlant::printVerify(const QList<PlantDrive> &drives)
{
    for (const PlantDrive &drive : drives) {
        if (drive.outcome == PlantDrive::Outcome::Different) {
            m_out << tr("%1: %n difference(s)", nullptr, int(drive.differences.size()))
                         .arg(drive.name())
                  << '\n';
            for (const ParameterDifference &difference : drive.differences) {
                const QString set = difference.set < 0 ? QString()
                                                       : tr("set %1").arg(difference.set);
                if (difference.kind == ParameterDifference::Kind::Different) {
                    m_out << QStringLiteral("  %1  %2  %3  ").arg(difference.id, difference.name, set)
                          << tr("file %1  drive %2").arg(difference.a, difference.b) << '\n';
                } else {
                    m_out << QStringLiteral("  %1  %2  ").arg(difference.id, difference.name)
                          << (difference.kind == ParameterDifference::Kind::OnlyInA
                                  ? tr("only in the file")
                                  : tr("only on the drive"))
                          << '\n';
                }
            }
        } else if (drive.outcome == PlantDrive::Outcome::Equal) {
            m_out << QStringLiteral("%1: %2").arg(drive.name(), PlantDrive::outcomeText(drive.outcome))
                  << '\n';
        } else {
            m_out << QStringLiteral("%1: %2: %3")
                         .arg(drive.name(), PlantDrive::outcomeText(drive.outcome), drive.reason)
                  << '\n';
        }
    }
    m_out << PlantDrive::summary(drives, PlantDrive::outcomeText(PlantDrive::Outcome::Equal)) << '\n';
}

void CliPlant::printDownload(const QList<PlantDrive> &drives)
{
    for (const PlantDrive &drive : drives) {
        m_out << QStringLiteral("%1: %2").arg(drive.name(), PlantDrive::outcomeText(drive.outcome));
        if (!drive.reason.isEmpty())
            m_out << QStringLiteral(": ") << drive.reason;
        m_out << '\n';
        for (const QString &line : drive.details.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
            m_out << QStringLiteral("  ") << line << '\n';
    }
    m_out << PlantDrive::summary(drives, m_plant.dryRun ? tr("checked, nothing written")
                                            : tr("downloaded or already equal"))
          << '\n';
}

void CliPlant::printVerifyJson(const QList<PlantDrive> &drives)
{
    // Fixed keys for scripts, whatever language the messages are in.
    static const QHash<PlantDrive::Outcome, QString> results{
        {PlantDrive::Outcome::Equal, QStringLiteral("equal")},
        {PlantDrive::Outcome::Different, QStringLiteral("different")},
        {PlantDrive::Outcome::OtherKind, QStringLiteral("other-kind")},
        {PlantDrive::Outcome::NoFile, QStringLiteral("no-file")},
        {PlantDrive::Outcome::Failed, QStringLiteral("failed")},
        {PlantDrive::Outcome::Unreachable, QStringLiteral("unreachable")},
        {PlantDrive::Outcome::Stopped, QStringLiteral("stopped")},
    };
    QJsonArray list;
    for (const PlantDrive &drive : drives) {
        QJsonObject entry{{QStringLiteral("link"), drive.link},
                          {QStringLiteral("result"), results.value(drive.outcome)}};
        entry.insert(QStringLiteral("address"),
                     drive.address < 0 ? QJsonValue() : QJsonValue(drive.address));
        if (!drive.file.isEmpty())
            entry.insert(QStringLiteral("file"), drive.file);
        if (!drive.reason.isEmpty())
            entry.insert(QStringLiteral("reason"), drive.reason);
        QJsonArray differences;
        for (const ParameterDifference &difference : drive.differences) {
            QJsonObject row{{QStringLiteral("id"), difference.id},
                            {QStringLiteral("name"), difference.name},
                            {QStringLiteral("file"), difference.a},
                            {QStringLiteral("drive"), difference.b}};
            row.insert(QStringLiteral("set"),
                       difference.set < 0 ? QJsonValue() : QJsonValue(difference.set));
            differences.append(row);
        }
        entry.insert(QStringLiteral("differences"), differences);
        list.append(entry);
    }
    m_out << QJsonDocument(QJsonObject{{QStringLiteral("drives"), list}}).toJson();
}

void CliPlant::end(int exitCode, const QString &message)
{
    if (m_finished)
        return;
    m_finished = true;
    m_out.flush();
    if (!message.isEmpty())
        m_err << QStringLiteral("drivedesk-cli: ") << message << Qt::endl;
    emit finished(exitCode);
}

} // namespace DriveDesk
