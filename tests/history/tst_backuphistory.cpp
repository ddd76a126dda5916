#include "../parameters/EditorSampleDrive.h"
#include "GitTestHome.h"

#include "history/BackupCommit.h"
#include "history/PlantHistory.h"
#include "parameters/ParameterDocument.h"

#include <QDate>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

ParameterDescription *find(DriveDescription &drive, quint16 address)
{
    return const_cast<ParameterDescription *>(drive.find(address));
}

using GitTest::git;

} // namespace

// A plant's backups made revisions: one commit a backup whose settings changed, its message in
// the drives' words, live values never a change; the history read back from the files; a
// revision's files extracted without touching the folder.
class TestBackupHistory : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(GitTest::useHome(m_home));
    }

    void aBackupIsCommittedWithItsChangesAndLiveValuesNeverCount()
    {
        QTemporaryDir folder;
        QString error;
        auto repository = BackupRepository::open(folder.path(), true, &error);
        QVERIFY2(repository, qPrintable(error));
        QVERIFY(!repository->hasCommits());

        DriveDescription drive = EditorSample::drive();
        QVERIFY(ParameterDocument::save(folder.filePath(QStringLiteral("cabinet-5.json")), drive));
        BackupCommit backup;
        backup.plantName = QStringLiteral("Line 3");
        backup.saved = {QStringLiteral("cabinet-5.json")};
        auto outcome = backup.commit(*repository, &error);
        QVERIFY2(outcome, qPrintable(error));
        QVERIFY(outcome->committed);
        QCOMPARE(git(folder.path(), {QStringLiteral("log"), QStringLiteral("-1"),
                                     QStringLiteral("--format=%an|%B")}),
                 QStringLiteral("Test Engineer|Line 3: backup, cabinet-5 changed\n\ncabinet-5 added"));

        // The actual frequency moved on: a live value, no change, no commit.
        find(drive, EditorSample::kFrequency)->values[0] = -4000;
        QVERIFY(ParameterDocument::save(folder.filePath(QStringLiteral("cabinet-5.json")), drive));
        outcome = backup.commit(*repository, &error);
        QVERIFY2(outcome, qPrintable(error));
        QVERIFY(!outcome->committed);
        QVERIFY(outcome->changes.isEmpty());
        QCOMPARE(git(folder.path(), {QStringLiteral("rev-list"), QStringLiteral("--count"),
                                     QStringLiteral("HEAD")}),
                 QStringLiteral("1"));

        find(drive, EditorSample::kRampTime)->values[0] = 750;
        QVERIFY(ParameterDocument::save(folder.filePath(QStringLiteral("cabinet-5.json")), drive));
        backup.message = QStringLiteral("after the service");
        outcome = backup.commit(*repository, &error);
        QVERIFY2(outcome, qPrintable(error));
        QVERIFY(outcome->committed);
        QCOMPARE(git(folder.path(), {QStringLiteral("log"), QStringLiteral("-1"),
                                     QStringLiteral("--format=%B")}),
                 QStringLiteral("after the service\n\ncabinet-5 oP.11 set 0: 5.00 s -> 7.50 s"));
        QCOMPARE(outcome->id, git(folder.path(), {QStringLiteral("rev-parse"), QStringLiteral("HEAD")}));

        // The history, newest first, computed from the files.
        auto history = readPlantHistory(*repository, {}, &error);
        QVERIFY2(history, qPrintable(error));
        QCOMPARE(history->size(), 2);
        QCOMPARE(history->at(0).subject, QStringLiteral("after the service"));
        QCOMPARE(history->at(0).author, QStringLiteral("Test Engineer"));
        QCOMPARE(history->at(0).changes.size(), 1);
        QCOMPARE(history->at(0).changes[0].lines(),
                 QStringList{QStringLiteral("cabinet-5 oP.11 set 0: 5.00 s -> 7.50 s")});
        QCOMPARE(history->at(1).changes[0].kind, DriveChange::Kind::Added);
        // A parameter (as typed, with its zero) lets through only the revision that changed it.
        history = readPlantHistory(*repository, {{}, QStringLiteral("OP.011")}, &error);
        QVERIFY2(history, qPrintable(error));
        QCOMPARE(history->size(), 1);
        history = readPlantHistory(*repository, {QStringLiteral("hoist"), {}}, &error);
        QVERIFY2(history, qPrintable(error));
        QVERIFY(history->isEmpty());

        // A drive the plant no longer has is gone from the next revision; its file stays.
        backup.saved.clear();
        backup.gone = {QStringLiteral("cabinet-5.json")};
        backup.message.clear();
        outcome = backup.commit(*repository, &error);
        QVERIFY2(outcome, qPrintable(error));
        QVERIFY(outcome->committed);
        QCOMPARE(outcome->changes[0].lines(), QStringList{QStringLiteral("cabinet-5 gone")});
        QVERIFY(QFile::exists(folder.filePath(QStringLiteral("cabinet-5.json"))));
    }

    void aRevisionIsNamedByIdTagOrDayAndExtractedAsItWas()
    {
        QTemporaryDir folder;
        QString error;
        auto repository = BackupRepository::open(folder.path(), true, &error);
        QVERIFY2(repository, qPrintable(error));
        DriveDescription drive = EditorSample::drive();
        const QString file = folder.filePath(QStringLiteral("hoist.json"));
        QVERIFY(ParameterDocument::save(file, drive));
        BackupCommit backup;
        backup.plantName = QStringLiteral("Line 3");
        backup.saved = {QStringLiteral("hoist.json")};
        QVERIFY(backup.commit(*repository, &error));
        const QString first = git(folder.path(), {QStringLiteral("rev-parse"), QStringLiteral("HEAD")});
        git(folder.path(), {QStringLiteral("tag"), QStringLiteral("commissioned")});
        find(drive, EditorSample::kRampTime)->values[0] = 750;
        QVERIFY(ParameterDocument::save(file, drive));
        QVERIFY(backup.commit(*repository, &error));
        const QString second = git(folder.path(), {QStringLiteral("rev-parse"), QStringLiteral("HEAD")});
        QVERIFY(first != second);

        QCOMPARE(repository->resolve(first.left(8), &error), first);
        QCOMPARE(repository->resolve(QStringLiteral("commissioned"), &error), first);
        QCOMPARE(repository->resolve(QDate::currentDate().toString(Qt::ISODate), &error), second);
        QVERIFY(!repository->resolve(QStringLiteral("2001-01-01"), &error));
        QVERIFY2(error.contains(QStringLiteral("no revision on or before 2001-01-01")), qPrintable(error));
        QVERIFY(!repository->resolve(QStringLiteral("no-such-tag"), &error));
        QVERIFY2(error.startsWith(QStringLiteral("'no-such-tag' is no revision of ")), qPrintable(error));
        QVERIFY(!repository->resolve(QStringLiteral("--all"), &error));

        QTemporaryDir target;
        QVERIFY2(repository->extract(first, target.path(), &error), qPrintable(error));
        const auto old = ParameterDocument::load(target.filePath(QStringLiteral("hoist.json")), &error);
        QVERIFY2(old, qPrintable(error));
        QCOMPARE(old->find(EditorSample::kRampTime)->values[0].value_or(-1), 500);
        // The folder and its index as they were.
        QCOMPARE(ParameterDocument::load(file)->find(EditorSample::kRampTime)->values[0].value_or(-1), 750);
        QCOMPARE(git(folder.path(), {QStringLiteral("status"), QStringLiteral("--porcelain")}), QString());
    }

    void aFolderThatIsNoRepositoryIsNamed()
    {
        QTemporaryDir folder;
        QString error;
        QVERIFY(!BackupRepository::open(folder.path(), false, &error));
        QVERIFY2(error.contains(QStringLiteral("is not a git repository of backups")), qPrintable(error));
        // A folder inside another repository is not that repository's to commit to.
        QVERIFY(BackupRepository::open(folder.path(), true, &error));
        QVERIFY(QDir(folder.path()).mkdir(QStringLiteral("inner")));
        QVERIFY(!BackupRepository::open(folder.filePath(QStringLiteral("inner")), false, &error));
    }

    // No user.name anywhere: the login name and host stand in, and the commit is made.
    void withoutUserNameTheLoginNameIsTheAuthor()
    {
        QTemporaryDir home;
        const QByteArray savedHome = qgetenv("HOME");
        const QByteArray savedConfig = qgetenv("XDG_CONFIG_HOME");
        const QByteArray savedUser = qgetenv("USER");
        qputenv("HOME", home.path().toUtf8());
        qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral(".config")).toUtf8());
        qputenv("USER", "plantuser");

        QTemporaryDir folder;
        QString error;
        auto repository = BackupRepository::open(folder.path(), true, &error);
        QVERIFY2(repository, qPrintable(error));
        QVERIFY(ParameterDocument::save(folder.filePath(QStringLiteral("hoist.json")), EditorSample::drive()));
        BackupCommit backup;
        backup.plantName = QStringLiteral("Line 3");
        backup.saved = {QStringLiteral("hoist.json")};
        const auto outcome = backup.commit(*repository, &error);

        qputenv("HOME", savedHome);
        qputenv("XDG_CONFIG_HOME", savedConfig);
        qputenv("USER", savedUser);
        QVERIFY2(outcome && outcome->committed, qPrintable(error));
        QCOMPARE(git(folder.path(), {QStringLiteral("log"), QStringLiteral("-1"),
                                     QStringLiteral("--format=%an")}),
                 QStringLiteral("plantuser"));
        QVERIFY(git(folder.path(), {QStringLiteral("log"), QStringLiteral("-1"),
                                    QStringLiteral("--format=%ae")})
                    .startsWith(QStringLiteral("plantuser@")));
    }

private:
    QTemporaryDir m_home;
};

QTEST_GUILESS_MAIN(TestBackupHistory)
#include "tst_backuphistory.moc"
