#include "Translations.h"
#include "parameters/GroupProperties.h"
#include "parameters/ParameterProperties.h"

#include <QTest>
#include <QTranslator>

using namespace DriveDesk;

namespace {

constexpr quint32 bit(int n)
{
    return 1u << n;
}

} // namespace

// Properties 1 and 2 (service 4) and group properties (service 10), bit by bit.
class TestParameterProperties : public QObject
{
    Q_OBJECT
private slots:
    // English as the programs show it: with its catalogue, which holds the plural forms.
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void passwordLevelsHaveNamesAndReadValues()
    {
        const QStringList english { QStringLiteral("CP read only"), QStringLiteral("CP read/write"),
                                    QStringLiteral("CP service"),   QStringLiteral("Application"),
                                    QStringLiteral("Drive mode"),   QStringLiteral("unused"),
                                    QStringLiteral("Security"),     QStringLiteral("Supervisor") };
        for (int level = 0; level < 8; ++level) {
            const auto password = PasswordLevel(level);
            QCOMPARE(passwordLevelName(password), english.at(level));
            QCOMPARE(passwordReadValue(password), -1 - level);
            QCOMPARE(passwordLevelFromReadValue(-1 - level), password);
        }
        {
            QTranslator german; // removes itself from the application when it goes
            QVERIFY(german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
            QVERIFY(QCoreApplication::installTranslator(&german));
            QCOMPARE(passwordLevelName(PasswordLevel::CpReadOnly), QStringLiteral("CP nur lesen"));
            QCOMPARE(passwordLevelName(PasswordLevel::Application), QStringLiteral("Applikation"));
        }
        QCOMPARE(passwordReadValue(PasswordLevel::Supervisor), -8);
        QVERIFY(!passwordLevelFromReadValue(0));
        QVERIFY(!passwordLevelFromReadValue(-9));
        QVERIFY(!passwordLevelFromReadValue(1234));
    }

    void properties1Fields()
    {
        // read Application (3), write Supervisor (7), long, no scaling result, signed
        const ParameterProperties p(3 | (7 << 3) | (2 << 6) | (3 << 8) | bit(10), 0);
        QCOMPARE(p.readLevel(), PasswordLevel::Application);
        QCOMPARE(p.writeLevel(), PasswordLevel::Supervisor);
        QCOMPARE(p.width(), ParameterProperties::Width::Long);
        QCOMPARE(p.scalingResult(), ParameterProperties::ScalingResult::None);
        QVERIFY(p.isSigned());
        QVERIFY(!p.isSetProgrammable());

        const ParameterProperties limits((1 << 12) | (2 << 14), 0);
        QCOMPARE(limits.lowerLimitType(), ParameterProperties::LimitType::VariableAtPowerOn);
        QCOMPARE(limits.upperLimitType(), ParameterProperties::LimitType::AlwaysVariable);
        QCOMPARE(limits.width(), ParameterProperties::Width::Byte);
        QVERIFY(!limits.isSigned());
    }

    void properties1Flags()
    {
        QVERIFY(ParameterProperties(bit(11), 0).isSetProgrammable());
        QVERIFY(ParameterProperties(bit(16), 0).isWritableWhileDisplayingActiveSet());
        QVERIFY(ParameterProperties(bit(17), 0).isScaledInBackground());
        QVERIFY(ParameterProperties(bit(18), 0).hasVariableDefault());
        QVERIFY(ParameterProperties(bit(19), 0).loadsDefaultOnlyForNewDevice());
        QVERIFY(ParameterProperties(0, 0).isProcessDataPermitted());
        QVERIFY(!ParameterProperties(bit(28), 0).isProcessDataPermitted());
        QVERIFY(ParameterProperties(bit(29), 0).isEncoderParameter());
        QVERIFY(ParameterProperties(bit(30), 0).isSystemParameter());
        QVERIFY(ParameterProperties(bit(31), 0).hasVariableScaling());

        const ParameterProperties types(bit(20) | bit(22) | bit(27), 0);
        QVERIFY(types.isVisibleForInverterType(0));
        QVERIFY(!types.isVisibleForInverterType(1));
        QVERIFY(types.isVisibleForInverterType(2));
        QVERIFY(types.isWritableForInverterType(3));
        QVERIFY(!types.isWritableForInverterType(0));
        QVERIFY(!types.isVisibleForInverterType(4));
        QVERIFY(!types.isVisibleForInverterType(-1));
    }

    void properties2Flags()
    {
        QVERIFY(ParameterProperties(0, bit(0)).isVisibleOnDisplay());
        QVERIFY(ParameterProperties(0, bit(1)).isWritableOnDisplay());
        QVERIFY(ParameterProperties(0, bit(2)).isVisibleInCombivis());
        QVERIFY(ParameterProperties(0, bit(3)).isWritableInCombivis());
        QCOMPARE(ParameterProperties(0, 1 << 4).enterMode(),
                 ParameterProperties::EnterMode::WithDot);
        QCOMPARE(ParameterProperties(0, 2 << 4).enterMode(),
                 ParameterProperties::EnterMode::WithoutDot);
        QCOMPARE(ParameterProperties(0, 1 << 6).displayFiltering(),
                 ParameterProperties::DisplayFiltering::TimeSlot);
        QCOMPARE(ParameterProperties(0, 2 << 6).displayFiltering(),
                 ParameterProperties::DisplayFiltering::Filter);
        QVERIFY(ParameterProperties(0, bit(8)).hasRotatingCount());
        QVERIFY(ParameterProperties(0, bit(9)).isChangedByInverter());
        QVERIFY(ParameterProperties(0, bit(10)).hidesValueWithoutPlaintext());
        QVERIFY(ParameterProperties(0, bit(11)).configurationFlag());
        QVERIFY(ParameterProperties(0, bit(12)).isWriteAlways());
        QVERIFY(ParameterProperties(0, bit(13)).isWriteOnly());
        QVERIFY(ParameterProperties(0, bit(14)).isExcludedFromCompleteList());
        QVERIFY(ParameterProperties(0, 0).isCpParameterPermitted());
        QVERIFY(!ParameterProperties(0, bit(15)).isCpParameterPermitted());
        QVERIFY(ParameterProperties(0, bit(16)).suppressesPlaintextDecimal());
        QVERIFY(ParameterProperties(0, bit(17)).isReadOnlyForTransferLists());
        QVERIFY(ParameterProperties(0, bit(18)).isProtected());
        QVERIFY(ParameterProperties(0, bit(19)).isWritableOnlyAtNop());
        QVERIFY(ParameterProperties(0, bit(20)).keepsDefaultWhileInvisible());
        QVERIFY(ParameterProperties(0, bit(21)).showsStateAtNopOrLs());
        QVERIFY(ParameterProperties(0, bit(22)).isIndirectlyAddressed());
        QVERIFY(ParameterProperties(0, bit(23)).isNotSetProgrammableForFocSynchron());
    }

    void eachFlagReadsOnlyItsOwnBit()
    {
        // All bits but one set: the accessor for that bit must see it clear.
        QVERIFY(!ParameterProperties(~bit(11), ~0u).isSetProgrammable());
        QVERIFY(!ParameterProperties(~bit(10), ~0u).isSigned());
        QVERIFY(!ParameterProperties(~0u, ~bit(3)).isWritableInCombivis());
        QVERIFY(!ParameterProperties(~0u, ~bit(12)).isWriteAlways());
        QVERIFY(!ParameterProperties(~0u, ~bit(17)).isReadOnlyForTransferLists());
        QCOMPARE(ParameterProperties(~(7u << 3), 0).writeLevel(), PasswordLevel::CpReadOnly);
        QCOMPARE(ParameterProperties(~(7u << 3), 0).readLevel(), PasswordLevel::Supervisor);
    }

    void readOnlyMeansNotWritableViaCombivis()
    {
        QVERIFY(ParameterProperties(0, 0).isReadOnly());
        QVERIFY(ParameterProperties(0, bit(1)).isReadOnly()); // writable on the display only
        QVERIFY(!ParameterProperties(0, bit(3)).isReadOnly());
    }

    void describeNamesEverySetFlag()
    {
        const ParameterProperties p(1 | (2 << 3) | (1 << 6) | bit(10) | bit(11) | bit(28),
                                    bit(2) | bit(3) | bit(12) | bit(13) | bit(14) | bit(17)
                                        | bit(19) | bit(25));
        const QStringList lines = p.describe();
        for (const char *expected :
             { "read level: CP read/write", "write level: CP service", "stored as word", "signed",
               "set-programmable", "not permitted as process data or for surveillance",
               "visible in COMBIVIS", "writable via COMBIVIS",
               "write always: written by upload and download",
               "write only: not read by upload, written by download",
               "excluded from the complete parameter list",
               "read-only for up/download lists: not written by download",
               "writable only at nop or error", "properties 2: free bit 25 set" }) {
            QVERIFY2(lines.contains(QString::fromUtf8(expected)),
                     qPrintable(QString::fromUtf8(expected) + QStringLiteral(" not in ")
                                + lines.join(QStringLiteral("; "))));
        }
        QVERIFY(!lines.contains(QStringLiteral("read-only via COMBIVIS")));
        QVERIFY(!lines.contains(QStringLiteral("protected")));

        QTranslator catalogue;
        QVERIFY(catalogue.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(QCoreApplication::installTranslator(&catalogue));
        const QStringList german = p.describe();
        QVERIFY(german.contains(QStringLiteral("satzprogrammierbar")));
        QVERIFY(german.contains(QStringLiteral("Passwortlevel Lesen: CP lesen/schreiben")));
        QCOMPARE(german.size(), lines.size());
    }

    void describeOfAllBitsNamesEachOnce()
    {
        const ParameterProperties all(~0u, ~0u);
        QStringList lines = all.describe();
        QCOMPARE(lines.removeDuplicates(), 0);
        QVERIFY(lines.contains(QStringLiteral("read level: Supervisor")));
        QVERIFY(lines.contains(QStringLiteral("storage width 3 (not used)")));
        QVERIFY(lines.contains(QStringLiteral("visible for inverter types 0, 1, 2, 3")));
        QVERIFY(lines.contains(QStringLiteral("protected")));
        QVERIFY(lines.contains(QStringLiteral("properties 2: free bit 31 set")));
        QVERIFY(
            ParameterProperties().describe().contains(QStringLiteral("read-only via COMBIVIS")));
    }

    void groupProperties()
    {
        const GroupProperties g(quint16(6 | bit(4)));
        QCOMPARE(g.passwordLevel(), PasswordLevel::Security);
        QVERIFY(!g.isVisibleOnDisplay());
        QVERIFY(g.isVisibleInCombivis());
        QCOMPARE(g.describe(),
                 (QStringList { QStringLiteral("password level: Security"),
                                QStringLiteral("visible in COMBIVIS") }));
        QVERIFY(GroupProperties(quint16(bit(3))).isVisibleOnDisplay());
        QTranslator german;
        QVERIFY(german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(QCoreApplication::installTranslator(&german));
        QCOMPARE(GroupProperties(quint16(bit(3) | bit(9))).describe(),
                 (QStringList { QStringLiteral("Passwortlevel: CP nur lesen"),
                                QStringLiteral("sichtbar auf der Anzeige"),
                                QStringLiteral("freies Bit 9 gesetzt") }));
    }
};

QTEST_GUILESS_MAIN(TestParameterProperties)
#include "tst_parameterproperties.moc"
