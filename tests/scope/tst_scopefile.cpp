#include "scope/ScopeFileReader.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeRecording.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>

using namespace DriveDesk;

namespace {

ScopeSample sampleAt(qsizetype index)
{
    ScopeSample sample;
    sample.time = 5000 + index * 2 - (index % 3 == 0 ? 1 : 0); // uneven, some repeated
    sample.wide
        = { qint32(index * 7919 - 100000), qint32(index % 2 ? -2147483647 - 1 : 2147483647) };
    sample.narrow = { qint16(index % 30000 - 15000), qint16(index % 2 ? -32768 : 32767) };
    return sample;
}

// A recording as one is taken: a scaled channel, an unknown source, a channel that is off, and
// a name that needs escaping in JSON.
ScopeFileHeader header()
{
    ScopeFileHeader header;
    header.started = QDateTime(QDate(2026, 11, 25), QTime(16, 57, 6, 123), Qt::UTC);
    header.source = QStringLiteral("HSP5 on /dev/ttyUSB0");
    header.channels[0].source = 0x0203;
    header.channels[0].setMask = 0x05;
    header.channels[0].id = QStringLiteral("ru.03");
    header.channels[0].name = QStringLiteral("Actual \"frequency\"\n");
    header.channels[0].scaling = DisplayScaling({ 0x0203, 10, -3, -100, quint16(18 | 1 << 8) });
    header.channels[2].source = 0x0200;
    header.channels[2].id = QStringLiteral("ru.00");
    header.channels[2].name = QStringLiteral("Status");
    header.channels[2].scaling = DisplayScaling({ 0x0200, 0, 0, 0, quint16(6 << 8) });
    header.channels[3].enabled = false;
    return header;
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

// The parts of a file: its magic line, its header's JSON and its records.
struct FileParts
{
    QByteArray magic;
    QByteArray json;
    QByteArray records;

    static FileParts of(const QByteArray &file)
    {
        const qsizetype lineEnd = file.indexOf('\n') + 1;
        const quint32 length = qFromLittleEndian<quint32>(file.constData() + lineEnd);
        return { file.left(lineEnd), file.mid(lineEnd + 4, length),
                 file.mid(lineEnd + 4 + length) };
    }
    QByteArray bytes() const
    {
        QByteArray length(4, '\0');
        qToLittleEndian(quint32(json.size()), length.data());
        return magic + length + json + records;
    }
};

QByteArray record(const ScopeSample &sample)
{
    QByteArray bytes(ScopeFileFormat::kRecordSize, '\0');
    ScopeFileFormat::encode(sample, bytes.data());
    return bytes;
}

} // namespace

// The recording file: written while recording, read back exactly, a cut-off end kept, and
// every damaged file refused with its reason and nothing half-loaded.
class TestScopeFile : public QObject
{
    Q_OBJECT

private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        m_path = m_dir.filePath(QStringLiteral("shot.ddscope"));
    }

    void roundTrip()
    {
        ScopeRecording recorded;
        const ScopeFileHeader start = header();
        recorded.started = start.started;
        recorded.source = start.source;
        recorded.channels = start.channels;
        const qsizetype count = 3 * SampleStore::kChunkSize + 5;
        for (qsizetype i = 0; i < count; ++i)
            QVERIFY(recorded.buffer.append(sampleAt(i)));

        ScopeFileWriter writer;
        QString error;
        QVERIFY2(writer.open(m_path, ScopeFileHeader::of(recorded), &error), qPrintable(error));
        // as a recording goes: a few samples, then the store's new ones in batches
        const std::array<ScopeSample, 3> first { sampleAt(0), sampleAt(1), sampleAt(2) };
        QVERIFY(writer.append(first.data(), qsizetype(first.size()), &error));
        QVERIFY(writer.append(recorded.buffer.samples(), 3, 1000, &error));
        QVERIFY(writer.flush(&error));
        QVERIFY(writer.append(recorded.buffer.samples(), 1000, 1000, &error)); // nothing new
        QVERIFY(writer.append(recorded.buffer.samples(), 1000, count, &error));
        QCOMPARE(writer.count(), count);
        QVERIFY2(writer.close(&error), qPrintable(error));

        ScopeRecording loaded;
        QStringList warnings;
        QVERIFY2(readScopeFile(m_path, loaded, &error, &warnings), qPrintable(error));
        QCOMPARE(warnings, QStringList());
        QCOMPARE(loaded.started, recorded.started);
        QCOMPARE(loaded.started.timeSpec(), Qt::UTC);
        QCOMPARE(loaded.source, recorded.source);
        QCOMPARE(loaded.channels, recorded.channels);
        QVERIFY(!loaded.channels[1].source);
        QVERIFY(!loaded.channels[3].enabled);
        QCOMPARE(loaded.buffer.count(), count);
        for (qsizetype i = 0; i < count; ++i)
            QCOMPARE(loaded.buffer.samples().at(i), recorded.buffer.samples().at(i));
        // the levels for drawing are built as the samples are loaded
        QCOMPARE(loaded.buffer.pyramid().count(), count);
    }

    // The math channels go with the recording: their definitions, not their values. A file
    // without them (as every file before them) has no "math" field and opens with none.
    void mathChannelsAreKeptWithTheRecording()
    {
        ScopeRecording recorded;
        recorded.channels = header().channels;
        for (qsizetype i = 0; i < 10; ++i)
            QVERIFY(recorded.buffer.append(sampleAt(i)));
        ScopeMathDefinition difference;
        difference.kind = ScopeMathDefinition::Kind::Difference;
        difference.sources = { 0, 2 };
        ScopeMathDefinition average;
        average.kind = ScopeMathDefinition::Kind::MovingAverage;
        average.window = 2.5;
        average.windowUnit = ScopeMathDefinition::WindowUnit::Milliseconds;
        recorded.math = { ScopeMathDefinition(), difference, average };

        ScopeFileWriter writer;
        QString error;
        QVERIFY2(writer.open(m_path, ScopeFileHeader::of(recorded), &error), qPrintable(error));
        QVERIFY(writer.append(recorded.buffer.samples(), 0, 10, &error));
        QVERIFY(writer.close(&error));
        QVERIFY(FileParts::of(readAll(m_path)).json.contains(
            "\"math\":[{\"kind\":\"derivative\",\"sources\":[0]},"));
        ScopeRecording loaded;
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.math, recorded.math);
        QCOMPARE(loaded.buffer.count(), 10);

        recorded.math.clear();
        QVERIFY(writer.open(m_path, ScopeFileHeader::of(recorded), &error));
        QVERIFY(writer.close(&error));
        QVERIFY(!FileParts::of(readAll(m_path)).json.contains("math"));
        loaded.math = { difference };
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.math, QList<ScopeMathDefinition>());
    }

    // A single shot's trigger goes with it, kept where it fired; a recording that is no shot
    // has no "trigger" field, as every file before it.
    void triggerIsKeptWithTheShot()
    {
        ScopeRecording recorded;
        recorded.channels = header().channels;
        for (qsizetype i = 0; i < 10; ++i)
            QVERIFY(recorded.buffer.append(sampleAt(i)));
        recorded.triggerMs = recorded.buffer.samples().time(4);
        // a part around it keeps it; a part without it has none
        QCOMPARE(recorded.excerpt(sampleAt(2).time, sampleAt(8).time)->triggerMs,
                 recorded.triggerMs);
        QVERIFY(!recorded.excerpt(sampleAt(6).time, sampleAt(8).time)->triggerMs);

        ScopeFileWriter writer;
        QString error;
        QVERIFY2(writer.open(m_path, ScopeFileHeader::of(recorded), &error), qPrintable(error));
        QVERIFY(writer.append(recorded.buffer.samples(), 0, 10, &error));
        QVERIFY(writer.close(&error));
        QVERIFY(FileParts::of(readAll(m_path)).json.contains("\"trigger\":5008"));
        ScopeRecording loaded;
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.triggerMs, std::optional<qint64>(5008));

        recorded.triggerMs.reset();
        QVERIFY(writer.open(m_path, ScopeFileHeader::of(recorded), &error));
        QVERIFY(writer.close(&error));
        QVERIFY(!FileParts::of(readAll(m_path)).json.contains("trigger"));
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QVERIFY(!loaded.triggerMs);
    }

    void layoutIsAsDocumented()
    {
        ScopeFileHeader start;
        start.source = QStringLiteral("sim");
        ScopeFileWriter writer;
        QVERIFY(writer.open(m_path, start));
        ScopeSample sample;
        sample.time = 0x0102030405060708;
        sample.wide = { -2, 0x11223344 };
        sample.narrow = { -3, 0x5566 };
        QVERIFY(writer.append(&sample, 1));
        QVERIFY(writer.close());
        const FileParts parts = FileParts::of(readAll(m_path));
        QCOMPARE(parts.magic, "DriveDesk scope 1\n");
        QVERIFY2(parts.json.startsWith("{\"channels\":[{\"enabled\":true,\"id\":\"\","),
                 parts.json.constData());
        QVERIFY(parts.json.contains("\"started\":null"));
        QCOMPARE(parts.records.toHex(),
                 QByteArray("0807060504030201"
                            "feffffff"
                            "44332211"
                            "fdff"
                            "6655"));
    }

    void headerOnlyIsAnEmptyRecording()
    {
        ScopeFileWriter writer;
        QVERIFY(writer.open(m_path, header()));
        QVERIFY(writer.close());
        ScopeRecording loaded;
        QString error;
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.buffer.count(), 0);
        QCOMPARE(loaded.channels, header().channels);
    }

    void flushedSamplesAreInTheFileWhileItIsOpen()
    {
        ScopeFileWriter writer;
        QVERIFY(writer.open(m_path, header()));
        const std::array<ScopeSample, 3> samples { sampleAt(0), sampleAt(1), sampleAt(2) };
        QVERIFY(writer.append(samples.data(), 3));
        QVERIFY(writer.flush());
        QVERIFY(writer.append(samples.data() + 2, 1)); // pending only, as at a crash
        ScopeRecording loaded;
        QString error;
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.buffer.count(), 3);
    }

    void incompleteLastSampleIsLeftOutWithAWarning()
    {
        ScopeFileWriter writer;
        QVERIFY(writer.open(m_path, header()));
        for (qsizetype i = 0; i < 100; ++i) {
            const ScopeSample sample = sampleAt(i);
            QVERIFY(writer.append(&sample, 1));
        }
        QVERIFY(writer.close());
        QByteArray bytes = readAll(m_path);
        bytes.chop(ScopeFileFormat::kRecordSize - 7);
        QVERIFY(writeAll(m_path, bytes));

        ScopeRecording loaded;
        QString error;
        QStringList warnings;
        QVERIFY2(readScopeFile(m_path, loaded, &error, &warnings), qPrintable(error));
        QCOMPARE(warnings,
                 QStringList { QStringLiteral("'%1' ends in an incomplete sample (7 "
                                              "byte(s)), which was left out: the "
                                              "recording was cut off")
                                   .arg(m_path) });
        QCOMPARE(loaded.buffer.count(), 99);
        QCOMPARE(loaded.buffer.samples().at(98), sampleAt(98));
    }

    void badFilesAreRefusedAndNothingIsLoaded_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("message"); // %1: the path

        const QString path = m_dir.filePath(QStringLiteral("good.ddscope"));
        ScopeFileWriter writer;
        QVERIFY(writer.open(path, header()));
        const std::array<ScopeSample, 3> samples { sampleAt(0), sampleAt(1), sampleAt(2) };
        QVERIFY(writer.append(samples.data(), 3));
        QVERIFY(writer.close());
        const FileParts good = FileParts::of(readAll(path));

        const QString notScope = QStringLiteral("'%1' is not a DriveDesk scope file");
        QTest::newRow("empty") << QByteArray() << notScope;
        QTest::newRow("text") << QByteArray("time,ru.03\r\n0,12.5\r\n") << notScope;
        QTest::newRow("no version") << QByteArray("DriveDesk scope \n") << notScope;
        QTest::newRow("version 0") << QByteArray("DriveDesk scope 0\n") << notScope;
        QTest::newRow("no line end") << QByteArray("DriveDesk scope 1") << notScope;

        FileParts newer = good;
        newer.magic = "DriveDesk scope 2\n";
        QTest::newRow("newer") << newer.bytes()
                               << QStringLiteral("'%1' is in scope file format 2 of a newer "
                                                 "DriveDesk; this version reads format 1");

        QTest::newRow("header cut short")
            << good.bytes().left(good.magic.size() + 4 + good.json.size() - 1)
            << QStringLiteral("'%1' is damaged: its header is cut short");
        QTest::newRow("no header length") << good.magic
                + "\x10\x00" << QStringLiteral("'%1' is damaged: its header is cut short");
        QTest::newRow("header length")
            << good.magic + QByteArray("\xff\xff\xff\x7f", 4) + good.json
            << QStringLiteral("'%1' is damaged: its header cannot be 2147483647 bytes long");

        const auto withJson = [&good](const QByteArray &from, const QByteArray &to) {
            FileParts changed = good;
            changed.json.replace(from, to);
            return changed.bytes();
        };
        QTest::newRow("not JSON")
            << withJson("{", "[")
            << QStringLiteral("'%1' has a damaged header: not JSON (missing value separator "
                              "at byte 12)");
        QTest::newRow("divisor") << withJson("\"divisor\":0", "\"divisor\":\"ten\"")
                                 << QStringLiteral(
                                        "'%1' has a damaged header: channels[2].scaling.divisor: "
                                        "expected an integer");
        QTest::newRow("set mask")
            << withJson("\"setMask\":5", "\"setMask\":256")
            << QStringLiteral("'%1' has a damaged header: channels[0].setMask: 256 is outside "
                              "0..255");
        QTest::newRow("source") << withJson("\"source\":515", "\"source\":\"ru.03\"")
                                << QStringLiteral(
                                       "'%1' has a damaged header: channels[0].source: expected an "
                                       "integer");
        QTest::newRow("started")
            << withJson("2026-11-25T16:57:06.123Z", "yesterday")
            << QStringLiteral("'%1' has a damaged header: started: expected a date and time "
                              "(ISO 8601) or null");
        QTest::newRow("missing field")
            << withJson("\"enabled\":false,", "")
            << QStringLiteral("'%1' has a damaged header: channels[3].enabled: missing");
        QTest::newRow("three channels")
            << withJson("},{\"enabled\":false", "}],\"x\":[{\"enabled\":false")
            << QStringLiteral("'%1' has a damaged header: channels: expected 4 channels, found 3");

        QTest::newRow("math kind")
            << withJson("\"source\":\"HSP5",
                        "\"math\":[{\"kind\":\"square\",\"sources\":[0]}],\"source\":\"HSP5")
            << QStringLiteral("'%1' has a damaged header: math[0]: kind: unknown kind \"square\"");
        QTest::newRow("math not a list")
            << withJson("\"source\":\"HSP5", "\"math\":7,\"source\":\"HSP5")
            << QStringLiteral("'%1' has a damaged header: math: expected an array");

        QTest::newRow("trigger")
            << withJson("\"source\":\"HSP5", "\"trigger\":\"soon\",\"source\":\"HSP5")
            << QStringLiteral("'%1' has a damaged header: trigger: expected an integer");

        FileParts backwards = good;
        backwards.records += record(sampleAt(0));
        QTest::newRow("out of order")
            << backwards.bytes()
            << QStringLiteral("'%1' is damaged: sample 4 is earlier than the one before it");
    }

    void badFilesAreRefusedAndNothingIsLoaded()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, message);
        const QString path = m_dir.filePath(QStringLiteral("bad.ddscope"));
        QVERIFY(writeAll(path, bytes));

        ScopeRecording out;
        out.source = QStringLiteral("before");
        QVERIFY(out.buffer.append(sampleAt(0)));
        QString error;
        QStringList warnings;
        QVERIFY(!readScopeFile(path, out, &error, &warnings));
        QCOMPARE(error, message.arg(path));
        QCOMPARE(warnings, QStringList());
        QCOMPARE(out.source, QStringLiteral("before"));
        QCOMPARE(out.buffer.count(), 1);
        QCOMPARE(out.channels, ScopeRecording().channels);
    }

    void unreadableFileNamesTheReason()
    {
        ScopeRecording out;
        QString error;
        const QString missing = m_dir.filePath(QStringLiteral("missing.ddscope"));
        QVERIFY(!readScopeFile(missing, out, &error));
        QCOMPARE(error, QStringLiteral("cannot read '%1': No such file or directory").arg(missing));
        QVERIFY(!readScopeFile(m_dir.path(), out, &error));
        QVERIFY2(error.startsWith(QStringLiteral("cannot read '%1': ").arg(m_dir.path())),
                 qPrintable(error));
    }

    void writerErrors()
    {
        ScopeFileWriter writer;
        QString error;
        const QString path = QStringLiteral("/nonexistent-folder/shot.ddscope");
        QVERIFY(!writer.open(path, header(), &error));
        QCOMPARE(error, QStringLiteral("cannot write '%1': No such file or directory").arg(path));
        QVERIFY(!writer.isOpen());
        const ScopeSample sample = sampleAt(0);
        QVERIFY(!writer.append(&sample, 1, &error));
        QCOMPARE(error, QStringLiteral("no recording file is open"));

        // a batch out of order is refused whole; the file stays readable
        QVERIFY(writer.open(m_path, header(), &error));
        const std::array<ScopeSample, 2> later { sampleAt(5), sampleAt(6) };
        QVERIFY(writer.append(later.data(), 2, &error));
        const std::array<ScopeSample, 2> mixed { sampleAt(7), sampleAt(1) };
        QVERIFY(!writer.append(mixed.data(), 2, &error));
        QCOMPARE(error,
                 QStringLiteral("cannot write '%1': a sample is earlier than the one "
                                "before it")
                     .arg(m_path));
        QVERIFY(!writer.append(mixed.data() + 1, 1, &error));
        QVERIFY(writer.append(mixed.data(), 1, &error));
        QCOMPARE(writer.count(), 3);
        QVERIFY(writer.close(&error));
        ScopeRecording loaded;
        QVERIFY2(readScopeFile(m_path, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.buffer.count(), 3);
    }

    void writeErrorNamesTheFileAndTheReason()
    {
        const QFileInfo full(QStringLiteral("/dev/full"));
        if (!full.exists() || full.isFile())
            QSKIP("needs the device /dev/full");
        ScopeFileWriter writer;
        QString error;
        // /dev/full takes the open but no byte: the header's write fails
        QVERIFY(!writer.open(full.filePath(), header(), &error));
        QCOMPARE(error, QStringLiteral("cannot write '/dev/full': No space left on device"));
        QVERIFY(!writer.isOpen());
        QVERIFY(QFileInfo::exists(full.filePath()));
    }

private:
    QTemporaryDir m_dir;
    QString m_path;
};

QTEST_GUILESS_MAIN(TestScopeFile)
#include "tst_scopefile.moc"
