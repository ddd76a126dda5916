// Scope storage: appending four channels of a million samples, drawing them into 1600 columns,
// the memory a sample takes, exporting them as CSV, writing and loading a recording file.
#include "scope/ScopeClock.h"
#include "scope/ScopeCsv.h"
#include "scope/ScopeFileReader.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeRecording.h"

#include <QBuffer>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>

using namespace DriveDesk;

namespace {

// Channels as a recording has them: scaled with one and two decimals, raw, variable decimals.
void describeChannels(ScopeRecording &recording)
{
    const auto scaled = [](qint16 divisor, int representation, quint16 unit) {
        ScopeChannel channel;
        channel.source = 0x0203;
        channel.id = QStringLiteral("ru.03");
        channel.name = QStringLiteral("Actual frequency");
        channel.scaling
            = DisplayScaling({ 0x0203, divisor, 1, 0, quint16(unit | representation << 8) });
        return channel;
    };
    recording.channels[0] = scaled(10, 1, 18);
    recording.channels[2] = scaled(100, 2, 21);
    recording.channels[3] = scaled(1000, 5, 37);
}

void exportCsv(const ScopeRecording &recording)
{
    QElapsedTimer timer;
    QBuffer memory;
    memory.open(QIODevice::WriteOnly);
    timer.start();
    QString error;
    if (!writeScopeCsv(memory, recording, {}, &error))
        std::printf("CSV failed: %s\n", qPrintable(error));
    const double memoryMs = timer.nsecsElapsed() / 1e6;
    std::printf("CSV of %lld rows x 4 channels into memory: %.1f ms (%.1f MB)\n",
                qlonglong(recording.buffer.count()), memoryMs, memory.size() / 1e6);

    QTemporaryDir dir;
    timer.restart();
    if (!saveScopeCsv(dir.filePath(QStringLiteral("scope.csv")), recording, {}, &error))
        std::printf("CSV failed: %s\n", qPrintable(error));
    std::printf("CSV of %lld rows x 4 channels saved to a file: %.1f ms\n",
                qlonglong(recording.buffer.count()), timer.nsecsElapsed() / 1e6);
}

// Written in batches of 1000 samples as a recording would, then loaded.
void writeAndLoadFile(const ScopeRecording &recording)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scope.ddscope"));
    QElapsedTimer timer;
    timer.start();
    ScopeFileWriter writer;
    QString error;
    bool written = writer.open(path, ScopeFileHeader::of(recording), &error);
    const qsizetype count = recording.buffer.count();
    for (qsizetype begin = 0; written && begin < count; begin += 1000)
        written
            = writer.append(recording.buffer.samples(), begin, qMin(begin + 1000, count), &error);
    if (!written || !writer.close(&error))
        std::printf("writing the recording file failed: %s\n", qPrintable(error));
    std::printf("recording file of %lld samples written in batches of 1000: %.1f ms (%.1f MB)\n",
                qlonglong(count), timer.nsecsElapsed() / 1e6, QFileInfo(path).size() / 1e6);

    timer.restart();
    ScopeRecording loaded;
    if (!readScopeFile(path, loaded, &error))
        std::printf("loading the recording file failed: %s\n", qPrintable(error));
    std::printf("recording file of %lld samples loaded (with the min/max levels): %.1f ms\n",
                qlonglong(loaded.buffer.count()), timer.nsecsElapsed() / 1e6);
}

} // namespace

int main()
{
    constexpr qsizetype kSamples = 1'000'000;
    constexpr int kColumns = 1600;

    ScopeRecording recording;
    describeChannels(recording);
    ScopeBuffer &buffer = recording.buffer;
    ScopeClock clock;
    QElapsedTimer timer;
    timer.start();
    quint16 timestamp = 0;
    for (qsizetype i = 0; i < kSamples; ++i) {
        timestamp += quint16(1 + i % 3); // uneven, wrapping every ~33,000 samples
        ScopeSample sample;
        sample.time = clock.unwrap(timestamp).time;
        sample.wide = { qint32(100000 * std::sin(i * 0.001)), qint32(i) };
        sample.narrow = { qint16(i % 4000 - 2000), qint16(i % 1000 == 0 ? 32767 : 0) };
        buffer.append(sample);
    }
    const double appendMs = timer.nsecsElapsed() / 1e6;
    std::printf("append %lld samples x 4 channels (with unwrapping): %.1f ms (%.1f ns a sample)\n",
                qlonglong(kSamples), appendMs, appendMs * 1e6 / kSamples);

    constexpr int kRounds = 20;
    timer.restart();
    qint64 sink = 0;
    for (int round = 0; round < kRounds; ++round) {
        for (int channel = 0; channel < ScopeSample::kChannelCount; ++channel) {
            for (const auto &column : buffer.decimate(channel, 0, buffer.count(), kColumns))
                sink += column.max - column.min;
        }
    }
    const double decimateMs = timer.nsecsElapsed() / 1e6 / kRounds;
    std::printf("decimate 4 channels of %lld samples to %d columns: %.3f ms\n", qlonglong(kSamples),
                kColumns, decimateMs);

    timer.restart();
    const qint64 last = buffer.samples().time(buffer.count() - 1);
    for (int round = 0; round < kRounds; ++round) {
        for (int channel = 0; channel < ScopeSample::kChannelCount; ++channel) {
            for (const auto &column : buffer.decimateTime(channel, last / 3, last, kColumns))
                sink += column.max - column.min;
        }
    }
    const double byTimeMs = timer.nsecsElapsed() / 1e6 / kRounds;
    std::printf("decimate 4 channels, two thirds of the time, to %d columns of equal time: "
                "%.3f ms\n",
                kColumns, byTimeMs);

    std::printf("bytes a sample: %.2f in the store, %.2f with the min/max levels (checksum %lld)\n",
                double(buffer.samples().bytesUsed()) / buffer.count(),
                double(buffer.bytesUsed()) / buffer.count(), qlonglong(sink));

    exportCsv(recording);
    writeAndLoadFile(recording);
    return 0;
}
