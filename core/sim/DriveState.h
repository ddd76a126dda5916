#pragma once

#include "MotorModel.h"
#include "ParameterDatabase.h"

#include <array>
#include <memory>
#include <vector>

namespace DriveDesk::Sim {

// One offline scope record (service 21): the four read channels at a 10 ms tick.
struct ScopeRecord
{
    quint16 timestamp = 0;
    std::array<qint32, 4> values {};
};

// Everything one simulated drive holds besides its metadata: the values of every parameter in
// every set, the password level in force, the motor and the offline scope recording.
// Not thread-safe; the owner serialises calls.
class DriveState
{
public:
    static constexpr int kRecordCount = 64;
    static constexpr qint64 kRecordPeriodMs = 10;

    DriveState(std::shared_ptr<const ParameterDatabase> db, int address, quint32 seed);

    const ParameterDatabase &db() const { return *m_db; }
    int address() const { return m_address; }
    quint32 seed() const { return m_seed; }
    qint32 serialNumber() const { return m_serialNumber; }
    void setSerialNumber(qint32 serial) { m_serialNumber = serial; }

    // Runs the motor and the timers up to `nowMs` (a monotonic clock). Time never runs back.
    void advanceTo(qint64 nowMs);
    qint64 clockMs() const { return m_clockMs; }
    qint64 uptimeMs() const { return m_clockMs - m_firstMs; }

    int activeSet() const; // Fr.02
    int setPointer() const; // Fr.09
    int passwordLevel() const { return m_passwordLevel; }
    // Service 8 answers characters rather than 7-segment patterns (DIN66019II).
    bool displayTextAsCharacters() const { return m_displayTextAsCharacters; }
    void setDisplayTextAsCharacters(bool characters) { m_displayTextAsCharacters = characters; }
    void setPasswordLevel(int level) { m_passwordLevel = level; }

    // The stored value (set 0 for a parameter that is not set-programmable).
    qint32 stored(int index, int set) const;
    // Stores into every set of `mask` (into the one value of other parameters).
    void store(int index, quint8 mask, qint32 value);
    // What the drive shows now: live signals computed, other parameters stored.
    qint32 value(int index, int set) const;
    // The value of a parameter the behaviour depends on, in the active set; `fallback` where
    // the data has no such parameter.
    qint32 setting(quint16 address, qint32 fallback) const;

    MotorModel &motor() { return m_motor; }
    const MotorModel &motor() const { return m_motor; }
    MotorSettings motorSettings() const;
    // The set speed the motor follows now: op.03 or the demo cycle, within op.10..op.13.
    double targetRpm(qint64 atMs) const;

    // The four read channels (Sy.16..Sy.23) now; 0 for a channel that is off.
    std::array<qint32, 4> readChannels() const;
    // Offline records, oldest first.
    int recordCount() const { return m_recordCount; }
    const ScopeRecord &record(int index) const;

private:
    void recordSample();

    std::shared_ptr<const ParameterDatabase> m_db;
    int m_address = 1;
    quint32 m_seed = 1;
    qint32 m_serialNumber = 10000000;
    std::vector<std::array<qint32, kSets>> m_values;
    int m_passwordLevel = 3;
    bool m_displayTextAsCharacters = false;
    MotorModel m_motor;
    bool m_started = false;
    qint64 m_firstMs = 0;
    qint64 m_clockMs = 0;
    std::array<ScopeRecord, kRecordCount> m_records {};
    int m_recordHead = 0;
    int m_recordCount = 0;
};

} // namespace DriveDesk::Sim
