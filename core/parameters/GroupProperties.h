#pragma once

#include "PasswordLevel.h"

#include <QCoreApplication>
#include <QStringList>

namespace DriveDesk {

// Reads the bit-coded properties of a parameter group (service 10, seed 002 2.12.1).
class GroupProperties
{
    Q_DECLARE_TR_FUNCTIONS(GroupProperties)
public:
    GroupProperties() = default;
    explicit GroupProperties(quint16 properties)
        : m_properties(properties)
    { }

    quint16 properties() const { return m_properties; }
    PasswordLevel passwordLevel() const { return PasswordLevel(m_properties & 0x07); }
    bool isVisibleOnDisplay() const { return m_properties & (1u << 3); }
    bool isVisibleInCombivis() const { return m_properties & (1u << 4); }

    // The password level, then every set flag (free bits 5-15 included), in words.
    QStringList describe() const;

private:
    quint16 m_properties = 0;
};

} // namespace DriveDesk
