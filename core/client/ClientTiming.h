#pragma once

#include "client/DriveClient.h"

#include <algorithm>

namespace DriveDesk {

// How long the client waits for an answer, from the options or from the line: the time the
// longest request and answer of the protocol take at the baud rate, plus a margin for the
// drive's response time (and for a device server's network, over TCP).
int answerTimeoutMs(const ConnectionSettings &settings, const ClientOptions &options);

// The short wait of a probe (FindDrivesJob) whose request and answer together take
// `exchangeCharacters` characters on the line; never longer than answerTimeoutMs().
int probeTimeoutMs(const ConnectionSettings &settings, const ClientOptions &options,
                   int exchangeCharacters);

// HSP5: how long the line must stay quiet before a drive that lost its step takes the next
// byte as the start of a telegram again: longer than the longest telegram, plus a margin.
int quietLineMs(const ConnectionSettings &settings);

// A drive has stopped answering once this many requests in a row were given up after every
// attempt without a valid answer: nothing at all came, or only garbage (ClientSilence.cpp).
constexpr int kUnansweredRequestsToStop = 4;
// ... and together they spent at least this many attempts. A client that does not try again
// (retries 0) would otherwise stop after one broken HSP5 answer on a busy line: the decoder
// finds its step again only after a quiet line, and the polls on the wire behind the broken
// answer are lost with it.
constexpr int kUnansweredAttemptsToStop = 2 * kUnansweredRequestsToStop;
// The requests in a row, each spending `attempts`, that stop a drive: both rules above.
constexpr int unansweredRequestsToStop(int attempts)
{
    const int forAttempts = (kUnansweredAttemptsToStop + attempts - 1) / std::max(attempts, 1);
    return std::max(kUnansweredRequestsToStop, forAttempts);
}
// A request whose attempts got a wrong checksum and garbage of another kind looks like a line
// with errors, and does not count towards kUnansweredRequestsToStop. But a line with errors still
// lets valid answers through: this many requests given up in a row, whatever they got, is a
// link that does not answer (an HSP5 link with a bit stuck in every answer). At 5 % flipped
// bytes, 32 attempts in a row without a valid answer do not happen in a lifetime of scans.
constexpr int kGivenUpRequestsToStop = 2 * kUnansweredRequestsToStop;

// The longest a client takes to decide that a drive stopped answering, from the moment it
// falls silent: up to the requests on the wire then timing out once, and then
// unansweredRequestsToStop() requests each spending every attempt (an answer timeout each, and
// HSP5's quiet line before each attempt while it recovers). HSP5 at 38400 baud: 2.0 s.
int silenceLimitMs(const ConnectionSettings &settings, const ClientOptions &options);

// The same for a drive that answers only with garbage: as for silence, except that HSP5 then
// waits for a quiet line from the drive at most twice the quiet line before each attempt (a
// stream that never ends would otherwise hold every request). HSP5 at 38400 baud: 2.4 s.
int garbageLimitMs(const ConnectionSettings &settings, const ClientOptions &options);

// With ClientOptions::idleCheckMs: the longest from the moment a drive on an idle line falls
// silent until the client reports it (driveSilentChanged): the idle time, then the check
// spending every attempt. HSP5 at 38400 baud, checked after 2 s: 2.5 s.
int idleSilenceLimitMs(const ConnectionSettings &settings, const ClientOptions &options);

// Bits on the line per character in the protocol's character format: 11 (8E1) or 10 (7E1).
int bitsPerCharacter(const ConnectionSettings &settings);

} // namespace DriveDesk
