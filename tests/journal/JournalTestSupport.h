#pragma once

#include "journal/Journal.h"

#include <QDateTime>
#include <QString>

namespace DriveDesk::JournalTest {

// An F5 on a DIN66019II bus, with every field of its identification.
inline JournalDrive busDrive(const QString &serialNumber = QStringLiteral("1234567"),
                             int address = 3)
{
    JournalDrive drive;
    drive.link = QStringLiteral("serial:/dev/ttyUSB0");
    drive.protocol = QStringLiteral("din66019ii");
    drive.address = address;
    drive.kind = QStringLiteral("F5 COMPACT 12.F5.C1G-3A0A");
    drive.softwareVersion = QStringLiteral("1.80");
    drive.serialNumber = serialNumber;
    return drive;
}

// One value written into set 2 of op.28, with every field given.
inline JournalEntry fullEntry()
{
    JournalEntry entry;
    entry.time = QDateTime(QDate(2026, 11, 24), QTime(9, 42, 5, 123), Qt::UTC);
    entry.user = QStringLiteral("anna");
    entry.host = QStringLiteral("line3-laptop");
    entry.program = QStringLiteral("drivedesk-cli 0.1.0");
    entry.drive = busDrive();
    entry.parameterId = QStringLiteral("op.28");
    entry.parameterAddress = 0x0A1C;
    entry.parameterName = QStringLiteral("Acceleration time");
    entry.set = 2;
    entry.before = { qint32(500), QStringLiteral("5.00 s") };
    entry.written = { qint32(750), QStringLiteral("7.50 s") };
    return entry;
}

// The entry begun `minutes` after 2026-11-24 10:00 local time, for the drive and user given.
inline JournalEntry entryAt(int minutes, const JournalDrive &drive, const QString &user,
                            const QString &parameterId = QStringLiteral("op.28"),
                            quint16 address = 0x0A1C)
{
    JournalEntry entry = fullEntry();
    entry.time = QDateTime(QDate(2026, 11, 24), QTime(10, 0), Qt::LocalTime).addSecs(minutes * 60);
    entry.drive = drive;
    entry.user = user;
    entry.parameterId = parameterId;
    entry.parameterAddress = address;
    return entry;
}

} // namespace DriveDesk::JournalTest
