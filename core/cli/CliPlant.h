#pragma once

#include "cli/CommandLine.h"
#include "journal/Journal.h"
#include "plant/PlantState.h"
#include "session/EditJournal.h"

#include <QHash>
#include <QObject>
#include <QTextStream>

#include <memory>

class QTemporaryDir;

class QCommandLineParser;

namespace DriveDesk {

class ConnectionOptions;

// `plant find|backup|verify|download PLANT [DIR]` parsed from a parser that has read the arguments;
// nothing and *error for arguments that do not make sense. The links come from the plant file:
// --connect and the options that go with it are refused.
std::optional<CliRequest> parsePlantCommand(const QCommandLineParser &parser,
                                            const ConnectionOptions &connection,
                                            const QStringList &positional, QString *error);

// Runs `drivedesk-cli plant`: reads the plant file (a bad one refused, exit 2, nothing sent),
// works through every drive with a PlantRun and prints a line per drive and a summary.
// Exit codes: 0 every drive done (found, saved, equal, downloaded), 1 a drive that failed, differs or could
// not be checked, 2 bad input, 3 no link answered, 130 interrupted (after the report).
class CliPlant : public QObject
{
    Q_OBJECT
public:
    explicit CliPlant(CliRequest request, QObject *parent = nullptr);
    ~CliPlant() override;

    void start();
    // Ctrl+C: every link stops after the value on its way; what was done is reported, and the
    // run ends with 130 as the other commands an interrupt ends.
    bool interrupt();

signals:
    void finished(int exitCode);

private:
    void onProgress(const QString &link, int address, int percent, const QString &what);
    void onFinished();
    void printFind(const QList<PlantDrive> &drives);
    void printBackup(const QList<PlantDrive> &drives);
    void printVerify(const QList<PlantDrive> &drives);
    void printVerifyJson(const QList<PlantDrive> &drives);
    void printDownload(const QList<PlantDrive> &drives);
    // --at: the files named as in the revision ("3f2a1bc04e11:cabinet-5.json"), not by the
    // temporary folder they were read from.
    void nameRevisionFiles(QList<PlantDrive> &drives) const;
    // "3 of 5 drives saved; unreachable: dead (cannot connect ...)".
    void end(int exitCode, const QString &message = {});

    CliRequest m_request;
    PlantRequest m_plant;
    PlantRun *m_run = nullptr;
    PlantState m_known; // what the run found out of each drive and link
    std::unique_ptr<Journal> m_journal; // a download's, unless --no-journal
    std::unique_ptr<EditJournal> m_editJournal;
    QTextStream m_out;
    QTextStream m_err;
    std::unique_ptr<QTemporaryDir> m_revision; // --at: the revision's files
    QString m_revisionId;
    QHash<QString, int> m_shown; // per drive: the last progress step printed
    bool m_finished = false;
    bool m_interrupted = false;
};

} // namespace DriveDesk
