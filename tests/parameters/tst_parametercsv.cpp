#include "EditorSampleDrive.h"

#include "Translations.h"
#include "parameters/ParameterCsv.h"

#include <QLocale>

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

// The CSV export: heading, one row per parameter, values per set, quoting as spreadsheets read it.
class TestParameterCsv : public QObject
{
    Q_OBJECT
private slots:
    void rowsHoldValuesPerSetAndQuoteWhatNeedsIt()
    {
        DriveDescription drive = EditorSample::drive();
        auto *ramp = const_cast<ParameterDescription *>(drive.find(kRampTime));
        ramp->name = QStringLiteral("Ramp, \"fast\"");
        auto *frequency = const_cast<ParameterDescription *>(drive.find(kMaxFrequency));
        frequency->values[7].reset();
        const QList<QByteArray> lines = parametersAsCsv(drive).split('\n');
        QCOMPARE(lines.first(), QByteArray("id,name,unit,set 0,set 1,set 2,set 3,set 4,set 5,"
                                           "set 6,set 7\r"));
        QCOMPARE(lines.size(), 1 + drive.parameterCount() + 1); // the last line end
        const auto row = [&lines](const QByteArray &id) {
            for (const QByteArray &line : lines) {
                if (line.startsWith(id + ','))
                    return line;
            }
            return QByteArray();
        };
        QCOMPARE(row("oP.11"), QByteArray("oP.11,\"Ramp, \"\"fast\"\"\",s,5.00,,,,,,,\r"));
        QCOMPARE(row("oP.10"),
                 QByteArray("oP.10,Max. frequency,Hz,50.00,60.00,50.00,50.00,50.00,50.00,50.00,?\r"));
    }

    // The window's export in German: as a German spreadsheet reads it, header and all, and
    // marked as UTF-8 so that "°C" does not turn into "Â°C".
    void aGermanSpreadsheetGetsItsOwnLanguage()
    {
        QVERIFY(installTranslations(QStringLiteral("de")));
        QLocale::setDefault(QLocale(QLocale::German));
        const QByteArray csv = parametersAsCsv(EditorSample::drive(), CsvStyle::forSpreadsheet());
        QLocale::setDefault(QLocale::c());
        QVERIFY(csv.startsWith("\xEF\xBB\xBF"));
        const QList<QByteArray> lines = csv.mid(3).split('\n');
        QCOMPARE(QString::fromUtf8(lines.first()),
                 QStringLiteral("Kennung;Name;Einheit;Satz 0;Satz 1;Satz 2;Satz 3;Satz 4;Satz 5;"
                                "Satz 6;Satz 7\r"));
        QVERIFY2(csv.contains("oP.10;Max. frequency;Hz;50,00;60,00"), csv.constData());
        // The command line's CSV stays as documented: English, no mark.
        QVERIFY(parametersAsCsv(EditorSample::drive()).startsWith("id,name,unit,"));
    }
};

QTEST_GUILESS_MAIN(TestParameterCsv)
#include "tst_parametercsv.moc"
