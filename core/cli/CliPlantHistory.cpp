// drivedesk-cli plant: the backups as revisions of a git repository.
#include "CliPlantHistory.h"

#include "history/BackupCommit.h"
#include "history/PlantHistory.h"
#include "plant/PlantRun.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace DriveDesk {

namespace {

class CliPlantHistoryText
{
    Q_DECLARE_TR_FUNCTIONS(CliPlantHistory)
};

QJsonObject changeJson(const DriveChange &change, const ParameterDifference &difference)
{
    QJsonObject row{{QStringLiteral("drive"), change.drive},
                    {QStringLiteral("kind"), DriveChange::kindKey(change.kind)},
                    {QStringLiteral("id"), difference.id},
                    {QStringLiteral("name"), difference.name},
                    {QStringLiteral("before"), difference.a},
                    {QStringLiteral("after"), difference.b},
                    {QStringLiteral("text"), DriveChange::differenceLine(change.drive, difference)}};
    row.insert(QStringLiteral("set"), difference.set < 0 ? QJsonValue() : QJsonValue(difference.set));
    return row;
}

QByteArray historyJson(const QList<PlantRevision> &revisions)
{
    QJsonArray list;
    for (const PlantRevision &revision : revisions) {
        QJsonArray changes;
        for (const DriveChange &change : revision.changes) {
            if (change.kind == DriveChange::Kind::Changed) {
                for (const ParameterDifference &difference : change.differences)
                    changes.append(changeJson(change, difference));
            } else {
                QJsonObject row{{QStringLiteral("drive"), change.drive},
                                {QStringLiteral("kind"), DriveChange::kindKey(change.kind)},
                                {QStringLiteral("text"), change.lines().join(QLatin1Char('\n'))}};
                if (!change.reason.isEmpty())
                    row.insert(QStringLiteral("reason"), change.reason);
                changes.append(row);
            }
        }
        list.append(QJsonObject{
            {QStringLiteral("id"), revision.id},
            {QStringLiteral("time"), revision.time.toOffsetFromUtc(revision.time.offsetFromUtc())
                                         .toString(Qt::ISODate)},
            {QStringLiteral("author"), revision.author},
            {QStringLiteral("email"), revision.email},
            {QStringLiteral("message"), revision.subject},
            {QStringLiteral("changes"), changes}});
    }
    return QJsonDocument(QJsonObject{{QStringLiteral("revisions"), list}}).toJson();
}

} // namespace

void addPlantHistoryOptions(QCommandLineParser &parser)
{
    parser.addOption(QCommandLineOption(QStringLiteral("commit")));
    parser.addOption(QCommandLineOption(QStringLiteral("message"), {}, QStringLiteral("text")));
    parser.addOption(QCommandLineOption(QStringLiteral("at"), {}, QStringLiteral("rev")));
}

bool refusePlantHistoryOptions(const QCommandLineParser &parser, QString *error)
{
    for (const char *name : {"commit", "message", "at"}) {
        if (parser.isSet(QLatin1String(name))) {
            *error = QStringLiteral("--%1 belongs to plant").arg(QLatin1String(name));
            return false;
        }
    }
    return true;
}

bool parsePlantHistoryOptions(const QCommandLineParser &parser, PlantRequest &plant,
                              QString *error)
{
    using Action = PlantRequest::Action;
    plant.commit = parser.isSet(QStringLiteral("commit"));
    if (parser.isSet(QStringLiteral("message"))) {
        plant.message = parser.value(QStringLiteral("message"));
        if (!plant.commit || plant.message.trimmed().isEmpty()) {
            *error = QStringLiteral("--message takes the text of the commit that --commit makes");
            return false;
        }
    }
    if (plant.commit && plant.action != Action::Backup) {
        *error = QStringLiteral("--commit belongs to plant backup");
        return false;
    }
    if (parser.isSet(QStringLiteral("at"))) {
        plant.at = parser.value(QStringLiteral("at"));
        if (plant.action != Action::Verify && plant.action != Action::Download) {
            *error = QStringLiteral("--at belongs to plant verify and plant download");
            return false;
        }
        if (plant.at.trimmed().isEmpty()) {
            *error = QStringLiteral("--at takes a revision: a commit id, a tag or a date like "
                                    "2026-11-24");
            return false;
        }
    }
    if (plant.action == Action::History) {
        plant.drive = parser.value(QStringLiteral("drive"));
        plant.parameter = parser.value(QStringLiteral("parameter"));
        if ((parser.isSet(QStringLiteral("drive")) && plant.drive.trimmed().isEmpty())
            || (parser.isSet(QStringLiteral("parameter")) && plant.parameter.trimmed().isEmpty())) {
            *error = QStringLiteral("--drive takes a drive's name (cabinet-5), --parameter an "
                                    "id (op.28)");
            return false;
        }
    }
    return true;
}

int printPlantHistory(const CliRequest &request, QTextStream &out, QString *error)
{
    const PlantRequest &plant = *request.plant;
    const auto repository = BackupRepository::open(plant.directory, false, error);
    if (!repository)
        return 2;
    HistoryFilter filter;
    filter.drive = plant.drive.trimmed();
    filter.parameter = plant.parameter.trimmed();
    const auto revisions = readPlantHistory(*repository, filter, error);
    if (!revisions)
        return 2;
    if (request.format == CliRequest::Format::Json) {
        out << historyJson(*revisions);
        return 0;
    }
    for (const PlantRevision &revision : *revisions) {
        out << QStringLiteral("%1  %2  %3  %4")
                   .arg(PlantRevision::shortId(revision.id),
                        revision.time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                        revision.author, revision.subject)
            << '\n';
        for (const DriveChange &change : revision.changes) {
            for (const QString &line : change.lines())
                out << QStringLiteral("  ") << line << '\n';
        }
    }
    if (revisions->isEmpty())
        out << CliPlantHistoryText::tr("no revision") << '\n';
    return 0;
}

bool commitAndPrintPlantBackup(const PlantRequest &request, const Plant &plant,
                               const QList<PlantDrive> &drives, QTextStream &out, QString *error)
{
    const auto committed
        = commitPlantBackup(request.directory, plant, drives, request.message, error);
    if (!committed)
        return false;
    if (!committed->savedAny) {
        out << CliPlantHistoryText::tr("no drive saved: nothing committed") << '\n';
        return true;
    }
    if (!committed->outcome.committed) {
        out << CliPlantHistoryText::tr("no setting changed since the last commit: nothing "
                                       "committed")
            << '\n';
        return true;
    }
    out << CliPlantHistoryText::tr("committed %1: %2")
               .arg(PlantRevision::shortId(committed->outcome.id), committed->subject)
        << '\n';
    for (const DriveChange &change : committed->outcome.changes) {
        for (const QString &line : change.lines())
            out << QStringLiteral("  ") << line << '\n';
    }
    return true;
}

} // namespace DriveDesk
