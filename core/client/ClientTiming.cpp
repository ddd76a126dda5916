#include "ClientTiming.h"

#include <QtGlobal>

#include <algorithm>

namespace DriveDesk {

namespace {

// The longest telegram either way: HSP5 field-bus data (64 bytes) with its header; DIN66019II
// the same data as hex characters.
constexpr int kLongestHsp5Telegram = 72;
constexpr int kLongestDinTelegram = 140;
// The drive's own response time (seed 003: typically 1..5 ms) and the operating system.
constexpr int kMarginMs = 50;
// A serial device server adds its buffering and the network.
constexpr int kTcpMarginMs = 200;
constexpr int kProbeMarginMs = 20;
constexpr int kTcpProbeMarginMs = 100;
// A drive's own idle detection and the operating system's timers.
constexpr int kQuietMarginMs = 5;
// A device server may gather bytes and send them on later.
constexpr int kTcpQuietMarginMs = 20;

qint32 lineBaudRate(const ConnectionSettings &settings)
{
    if (settings.kind == ConnectionSettings::Kind::Simulated && settings.simulation.paced)
        return std::max(settings.simulation.baudRate, 1);
    return std::max(settings.baudRate, 1);
}

int lineTimeMs(const ConnectionSettings &settings, int characters)
{
    const qint64 bits = qint64(characters) * bitsPerCharacter(settings);
    return int((bits * 1000 + lineBaudRate(settings) - 1) / lineBaudRate(settings));
}

int simulatedLatencyMs(const ConnectionSettings &settings)
{
    if (settings.kind != ConnectionSettings::Kind::Simulated)
        return 0;
    return (std::max(settings.simulation.replyLatencyUs, 0) + 999) / 1000;
}

} // namespace

int bitsPerCharacter(const ConnectionSettings &settings)
{
    const int start = 1;
    const int data = int(settings.effectiveDataBits());
    const int parity = settings.effectiveParity() == QSerialPort::NoParity ? 0 : 1;
    const int stop = settings.effectiveStopBits() == QSerialPort::OneStop ? 1 : 2;
    return start + data + parity + stop;
}

int answerTimeoutMs(const ConnectionSettings &settings, const ClientOptions &options)
{
    if (options.timeoutMs > 0)
        return options.timeoutMs;
    const int longest = settings.protocol == Protocol::Hsp5 ? kLongestHsp5Telegram
                                                            : kLongestDinTelegram;
    const int margin = settings.kind == ConnectionSettings::Kind::Tcp ? kTcpMarginMs : kMarginMs;
    return lineTimeMs(settings, 2 * longest) + simulatedLatencyMs(settings) + margin;
}

int quietLineMs(const ConnectionSettings &settings)
{
    const int margin = settings.kind == ConnectionSettings::Kind::Tcp ? kTcpQuietMarginMs
                                                                      : kQuietMarginMs;
    return lineTimeMs(settings, kLongestHsp5Telegram) + margin;
}

int probeTimeoutMs(const ConnectionSettings &settings, const ClientOptions &options,
                   int exchangeCharacters)
{
    const int margin = settings.kind == ConnectionSettings::Kind::Tcp ? kTcpProbeMarginMs
                                                                      : kProbeMarginMs;
    const int probe = lineTimeMs(settings, exchangeCharacters) + simulatedLatencyMs(settings)
                      + margin;
    return std::min(probe, answerTimeoutMs(settings, options));
}

int silenceLimitMs(const ConnectionSettings &settings, const ClientOptions &options)
{
    const int attempts = 1 + std::max(options.retries, 0);
    const int quietLine = settings.protocol == Protocol::Hsp5 ? quietLineMs(settings) : 0;
    const int timeout = answerTimeoutMs(settings, options);
    return timeout + unansweredRequestsToStop(attempts) * attempts * (timeout + quietLine);
}

int garbageLimitMs(const ConnectionSettings &settings, const ClientOptions &options)
{
    const int attempts = 1 + std::max(options.retries, 0);
    const int busyLine = settings.protocol == Protocol::Hsp5 ? 2 * quietLineMs(settings) : 0;
    const int timeout = answerTimeoutMs(settings, options);
    return timeout + unansweredRequestsToStop(attempts) * attempts * (timeout + busyLine);
}

int idleSilenceLimitMs(const ConnectionSettings &settings, const ClientOptions &options)
{
    const int attempts = 1 + std::max(options.retries, 0);
    const int quietLine = settings.protocol == Protocol::Hsp5 ? quietLineMs(settings) : 0;
    return options.idleCheckMs + attempts * (answerTimeoutMs(settings, options) + quietLine);
}

} // namespace DriveDesk
