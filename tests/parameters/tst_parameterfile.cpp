#include "SampleDrive.h"
#include "parameters/ParameterDocument.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using namespace DriveDesk;
using namespace DriveDesk::TestData;

namespace {

// Root's permission override dropped while a read-only directory must stay read-only.
class WithoutRootOverride
{
public:
    WithoutRootOverride()
    {
        if (::geteuid() == 0)
            m_dropped = ::seteuid(65534) == 0;
    }
    ~WithoutRootOverride()
    {
        if (m_dropped)
            (void)::seteuid(0);
    }
    WithoutRootOverride(const WithoutRootOverride &) = delete;
    WithoutRootOverride &operator=(const WithoutRootOverride &) = delete;

private:
    bool m_dropped = false;
};

} // namespace

// Saving and loading parameter files: a failed save never costs the old file.
class TestParameterFile : public QObject
{
    Q_OBJECT
private slots:
    void saveAndLoad()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("drive.json"));
        QString error;
        QVERIFY2(ParameterDocument::save(path, sample(), &error), qPrintable(error));
        const std::optional<DriveDescription> loaded = ParameterDocument::load(path, &error);
        QVERIFY2(loaded, qPrintable(error));
        QVERIFY(*loaded == sample());

        DriveDescription other = sample();
        other.groups.removeLast();
        QVERIFY(ParameterDocument::save(path, other, &error));
        QVERIFY(*ParameterDocument::load(path) == other);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files),
                 QStringList { QStringLiteral("drive.json") });
    }

    void loadErrorsNameTheFile()
    {
        QTemporaryDir dir;
        QString error;
        const QString missing = dir.filePath(QStringLiteral("missing.json"));
        QVERIFY(!ParameterDocument::load(missing, &error));
        QVERIFY2(error.startsWith(QStringLiteral("cannot read '%1'").arg(missing)),
                 qPrintable(error));

        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "drivedesk-parameters", "version": 1)");
        file.close();
        QVERIFY(!ParameterDocument::load(broken, &error));
        QVERIFY2(error.startsWith(broken + QStringLiteral(": not valid JSON")), qPrintable(error));

        const QString huge = dir.filePath(QStringLiteral("huge.json"));
        QFile big(huge);
        QVERIFY(big.open(QIODevice::WriteOnly));
        QVERIFY(big.resize(ParameterDocument::kMaxFileSize + 1)); // sparse
        big.close();
        QVERIFY(!ParameterDocument::load(huge, &error));
        QVERIFY2(error.contains(QStringLiteral("too large")), qPrintable(error));
    }

    void failedSaveLeavesTheOldFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile::setPermissions(dir.path(),
                              QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner
                                  | QFile::ReadOther | QFile::ExeOther);
        const QString folder = dir.filePath(QStringLiteral("readonly"));
        QVERIFY(QDir().mkdir(folder));
        const QString path = folder + QStringLiteral("/drive.json");
        QVERIFY(ParameterDocument::save(path, sample()));
        QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadOther);
        const QByteArray old = ParameterDocument::toJson(sample());
        QFile::setPermissions(
            folder, QFile::ReadOwner | QFile::ExeOwner | QFile::ReadOther | QFile::ExeOther);

        DriveDescription changed = sample();
        changed.protocol = QStringLiteral("din66019ii");
        bool saved = false;
        QString error;
        bool permissionsHold = true;
        {
            const WithoutRootOverride asUser;
            QFile probe(folder + QStringLiteral("/probe"));
            if (probe.open(QIODevice::WriteOnly)) {
                permissionsHold = false;
                probe.remove();
            } else {
                saved = ParameterDocument::save(path, changed, &error);
            }
        }
        QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        if (!permissionsHold)
            QSKIP("this process may write to read-only directories");

        QVERIFY(!saved);
        QVERIFY2(error.startsWith(QStringLiteral("cannot write '%1'").arg(path)),
                 qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), old);
        QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden),
                 QStringList { QStringLiteral("drive.json") });
    }

    void saveToAFolderThatIsNotThereFails()
    {
        QTemporaryDir dir;
        QString error;
        const QString path = dir.filePath(QStringLiteral("no/such/folder/drive.json"));
        QVERIFY(!ParameterDocument::save(path, sample(), &error));
        QVERIFY2(error.startsWith(QStringLiteral("cannot write")), qPrintable(error));
        QVERIFY(!QFile::exists(path));
    }
};

QTEST_GUILESS_MAIN(TestParameterFile)
#include "tst_parameterfile.moc"
