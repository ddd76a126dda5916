#pragma once

#include "PasswordLevel.h"

#include <QCoreApplication>
#include <QStringList>

namespace DriveDesk {

// Reads the bit-coded properties 1 and 2 of a parameter (service 4, seed 002 2.6.1 and 2.6.2).
class ParameterProperties
{
    Q_DECLARE_TR_FUNCTIONS(ParameterProperties)
public:
    enum class Width : quint8 { Byte = 0, Word = 1, Long = 2, Unused = 3 };
    enum class ScalingResult : quint8 { Byte = 0, Word = 1, Long = 2, None = 3 };
    enum class LimitType : quint8 {
        Constant = 0,
        VariableAtPowerOn = 1,
        AlwaysVariable = 2,
        Unused = 3
    };
    enum class EnterMode : quint8 { None = 0, WithDot = 1, WithoutDot = 2, Unused = 3 };
    enum class DisplayFiltering : quint8 { None = 0, TimeSlot = 1, Filter = 2, Unused = 3 };

    static constexpr int kInverterTypes = 4;

    ParameterProperties() = default;
    ParameterProperties(quint32 properties1, quint32 properties2)
        : m_properties1(properties1)
        , m_properties2(properties2)
    { }

    quint32 properties1() const { return m_properties1; }
    quint32 properties2() const { return m_properties2; }

    // Properties 1
    PasswordLevel readLevel() const { return PasswordLevel(field1(0, 3)); }
    PasswordLevel writeLevel() const { return PasswordLevel(field1(3, 3)); }
    Width width() const { return Width(field1(6, 2)); }
    ScalingResult scalingResult() const { return ScalingResult(field1(8, 2)); }
    bool isSigned() const { return bit1(10); }
    bool isSetProgrammable() const { return bit1(11); }
    LimitType lowerLimitType() const { return LimitType(field1(12, 2)); }
    LimitType upperLimitType() const { return LimitType(field1(14, 2)); }
    bool isWritableWhileDisplayingActiveSet() const { return bit1(16); }
    bool isScaledInBackground() const { return bit1(17); }
    bool hasVariableDefault() const { return bit1(18); }
    // Security mode: the default is loaded only for a new device, not on a new version,
    // type, LTK or when the default set is copied.
    bool loadsDefaultOnlyForNewDevice() const { return bit1(19); }
    // type 0..3; false for any other type.
    bool isVisibleForInverterType(int type) const;
    bool isWritableForInverterType(int type) const;
    // Bit 28 set means "not permitted".
    bool isProcessDataPermitted() const { return !bit1(28); }
    bool isEncoderParameter() const { return bit1(29); }
    bool isSystemParameter() const { return bit1(30); }
    bool hasVariableScaling() const { return bit1(31); }

    // Properties 2
    bool isVisibleOnDisplay() const { return bit2(0); }
    bool isWritableOnDisplay() const { return bit2(1); }
    bool isVisibleInCombivis() const { return bit2(2); }
    bool isWritableInCombivis() const { return bit2(3); }
    EnterMode enterMode() const { return EnterMode(field2(4, 2)); }
    DisplayFiltering displayFiltering() const { return DisplayFiltering(field2(6, 2)); }
    bool hasRotatingCount() const { return bit2(8); }
    bool isChangedByInverter() const { return bit2(9); }
    // Bit 10: a value without a plaintext is not displayed at all (instead of scaled).
    bool hidesValueWithoutPlaintext() const { return bit2(10); }
    bool configurationFlag() const { return bit2(11); }
    bool isWriteAlways() const { return bit2(12); }
    bool isWriteOnly() const { return bit2(13); }
    bool isExcludedFromCompleteList() const { return bit2(14); }
    // Bit 15 set means "not permitted".
    bool isCpParameterPermitted() const { return !bit2(15); }
    bool suppressesPlaintextDecimal() const { return bit2(16); }
    bool isReadOnlyForTransferLists() const { return bit2(17); }
    bool isProtected() const { return bit2(18); }
    bool isWritableOnlyAtNop() const { return bit2(19); }
    bool keepsDefaultWhileInvisible() const { return bit2(20); }
    bool showsStateAtNopOrLs() const { return bit2(21); }
    bool isIndirectlyAddressed() const { return bit2(22); }
    bool isNotSetProgrammableForFocSynchron() const { return bit2(23); }

    // Not writable via COMBIVIS, i.e. by us (properties 2 bit 3 clear).
    bool isReadOnly() const { return !isWritableInCombivis(); }

    // The password levels and the storage, then every set flag, in words.
    QStringList describe() const;

private:
    quint32 field1(int shift, int bits) const
    {
        return (m_properties1 >> shift) & ((1u << bits) - 1);
    }
    quint32 field2(int shift, int bits) const
    {
        return (m_properties2 >> shift) & ((1u << bits) - 1);
    }
    bool bit1(int bit) const { return m_properties1 & (1u << bit); }
    bool bit2(int bit) const { return m_properties2 & (1u << bit); }

    quint32 m_properties1 = 0;
    quint32 m_properties2 = 0;
};

} // namespace DriveDesk
