#pragma once

#include "PlantFile.h"
#include "client/DriveClient.h"
#include "parameters/ParameterComparison.h"

#include <QCoreApplication>
#include <QList>
#include <QObject>
#include <QString>

#include <memory>

namespace DriveDesk {

class EditJournal;
class PlantLinkRun;

// What one drive of a plant came to in a PlantRun.
struct PlantDrive
{
    Q_DECLARE_TR_FUNCTIONS(PlantDrive)
public:
    enum class Outcome : quint8 {
        Found,       // find: the drive answered
        Saved,       // backup: read whole and saved
        Equal,       // verify: every setting as in its file
        Different,   // verify: settings differ (differences)
        OtherKind,   // verify: the file was made for another kind of drive
        NoFile,      // verify: there is no file for the drive
        Failed,      // read, saved or compared only in part (reason); nothing saved
        Unreachable, // the link could not be opened or went away (reason)
        Stopped,     // the run was stopped before the drive was done
        Written,     // download: every value to write written and read back (details)
        Unchanged,   // download: the settings already equal the file; nothing written
        Planned,     // download --dry-run: what would be written (details); nothing written
    };

    QString link;
    int address = -1; // -1 on an HSP5 link: one drive a line, no address
    Outcome outcome = Outcome::Failed;
    QString identification; // find: FoundDrive::identification()
    QString file;           // backup, verify: the parameter file
    QString reason;         // why it failed, was unreachable or stopped
    int parameters = 0;     // backup: parameters saved
    QList<ParameterDifference> differences; // verify: a = the file, b = the drive
    QString details; // download: the report, or with a dry run the plan, as text

    // "cabinet-5", or the link's name for a drive without an address.
    QString name() const;
    bool isGood() const
    {
        return outcome == Outcome::Found || outcome == Outcome::Saved || outcome == Outcome::Equal
            || outcome == Outcome::Written || outcome == Outcome::Unchanged
            || outcome == Outcome::Planned;
    }
    // The drive said something back, whatever it said (a difference, another kind of drive).
    bool answered() const;
    // "saved", "equal", "another kind of drive", ...
    static QString outcomeText(Outcome outcome);
    // One line for a run: "2 of 3 drives equal; not: cabinet-5 (different)", each drive that
    // did not end well named with its reason (or its outcome where it has none).
    static QString summary(const QList<PlantDrive> &drives, const QString &goodText);
};

// Works through every drive of a plant, as `drivedesk-cli plant` and a window both run it:
// finds the drives on each link, backs each up to a parameter file (UploadRun, saveUpload),
// checks each against its file (settings only, compareDescriptions), or downloads each file to
// its drive (DownloadRun; a drive whose settings equal its file is left alone). Links run side
// by side (PlantLinkRun), each over one connection with a client (and worker thread) of its
// own; the drives of one bus one after another on it.
// A link that fails fails only its own drives. A DIN link without addresses is searched first.
// Thread: the caller's.
class PlantRun : public QObject
{
    Q_OBJECT
public:
    enum class Task : quint8 { Find, Backup, Verify, Download };

    // `directory`: where the parameter files are (backup, verify, download).
    PlantRun(Plant plant, Task task, QString directory, LinkMaker makeLink,
             QObject *parent = nullptr);
    ~PlantRun() override;

    void setClientOptions(const ClientOptions &options) { m_clientOptions = options; }
    // How a drive is read (where its metadata comes from).
    void setReading(const ScanOptions &reading) { m_reading = reading; }
    // The language of the drives' texts.
    void setLanguage(Language language) { m_language = language; }
    // Download: only plan (and report what would be written); write despite the checks.
    void setDownloadOptions(bool dryRun, bool force)
    {
        m_dryRun = dryRun;
        m_force = force;
    }

    // Download: every value written is journaled there; none: not journaled. Outlives the run.
    void setJournal(EditJournal *journal) { m_journal = journal; }

    void start();
    // Ends every link after the value on its way; drives not done are Stopped.
    void stop();
    bool isRunning() const;
    Task task() const { return m_task; }

    // The plant, with the addresses a search found on each DIN link whose search went to the
    // end (links that could not be searched keep theirs).
    const Plant &plant() const { return m_plant; }
    QList<PlantDrive> drives() const; // in plant order, then address
    // The file of the drive at `address` on `link` ("DIR/cabinet-5.json", "DIR/hoist.json").
    static QString fileFor(const QString &directory, const PlantLink &link, int address);

signals:
    // One link's progress: the drive it is at (-1 for a search) and what it does.
    void progress(const QString &link, int address, int percent, const QString &what);
    void driveDone(const DriveDesk::PlantDrive &drive);
    // Every link is done; always after start() and stop() have returned.
    void finished();

private:
    Plant m_plant;
    const Task m_task;
    const QString m_directory;
    LinkMaker m_makeLink;
    ClientOptions m_clientOptions;
    ScanOptions m_reading;
    Language m_language = Language::English;
    QList<PlantLinkRun *> m_links; // in plant order
    int m_linksRunning = 0;
    bool m_dryRun = false;
    bool m_force = false;
    EditJournal *m_journal = nullptr;
    bool m_stopping = false;
    bool m_started = false;
};

} // namespace DriveDesk
