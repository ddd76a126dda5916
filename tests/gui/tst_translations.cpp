#include "tst_mainwindow_support.h"

#include "bus/LinkFactory.h"
#include "main/ConnectionDialog.h"
#include "client/Reply.h"
#include "edit/EditController.h"
#include "link/ConnectionSettings.h"
#include "model/ParameterModel.h"
#include "monitor/TrafficFormat.h"
#include "parameters/GroupProperties.h"
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterProperties.h"
#include "parameters/ParameterId.h"
#include "Translations.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QSignalSpy>
#include <QTest>
#include <QTabBar>
#include <QTabWidget>
#include <QToolBar>
#include <QTranslator>
#include <QUndoStack>
#include <QXmlStreamReader>

using namespace DriveDesk;

namespace {

// One <message> of a Qt Linguist file.
struct CatalogueEntry
{
    QString context;
    QString source;
    QString comment;
    QString translationType; // "", "unfinished", "vanished" or "obsolete"
    QStringList forms;       // the translation, or its numerus forms
    bool numerus = false;

    QString key() const { return context + QLatin1Char('|') + source + QLatin1Char('|') + comment; }
};

struct Catalogue
{
    QString language;
    QList<CatalogueEntry> entries;
    QString error;
};

Catalogue readCatalogue(const QString &path)
{
    Catalogue catalogue;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        catalogue.error = QStringLiteral("cannot read %1: %2").arg(path, file.errorString());
        return catalogue;
    }
    QXmlStreamReader xml(&file);
    QString context;
    CatalogueEntry entry;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("TS")) {
                catalogue.language = xml.attributes().value(QLatin1String("language")).toString();
            } else if (name == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1String("message")) {
                entry = CatalogueEntry();
                entry.context = context;
                entry.numerus = xml.attributes().value(QLatin1String("numerus"))
                                == QLatin1String("yes");
            } else if (name == QLatin1String("source")) {
                entry.source = xml.readElementText();
            } else if (name == QLatin1String("comment")) {
                entry.comment = xml.readElementText();
            } else if (name == QLatin1String("translation")) {
                entry.translationType = xml.attributes().value(QLatin1String("type")).toString();
                if (!entry.numerus)
                    entry.forms << xml.readElementText();
            } else if (name == QLatin1String("numerusform")) {
                entry.forms << xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            catalogue.entries << entry;
        }
    }
    if (xml.hasError())
        catalogue.error = QStringLiteral("%1: %2 at line %3")
                              .arg(path, xml.errorString())
                              .arg(xml.lineNumber());
    return catalogue;
}

// %1..%99, %n and %Ln: what a translation must keep for arg() and the count to land.
QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("%(L?n|[1-9][0-9]?)"));
    QSet<QString> found;
    for (auto it = pattern.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured());
    return found;
}

// How many keyboard accelerators ("&File"; not "&&" nor a lone "& ") a text holds.
int accelerators(const QString &text)
{
    int count = 0;
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text.at(i) != QLatin1Char('&'))
            continue;
        if (text.at(i + 1) == QLatin1Char('&'))
            ++i;
        else if (!text.at(i + 1).isSpace())
            ++count;
    }
    return count;
}

// Every way an entry falls short of a finished translation, in words.
QStringList problemsOf(const CatalogueEntry &entry)
{
    QStringList problems;
    if (!entry.translationType.isEmpty())
        problems << entry.translationType;
    if (entry.numerus && entry.forms.size() != 2)
        problems << QStringLiteral("%1 numerus forms, expected 2").arg(entry.forms.size());
    for (const QString &form : entry.forms) {
        if (form.isEmpty()) {
            problems << QStringLiteral("empty translation");
            continue;
        }
        if (placeholders(form) != placeholders(entry.source))
            problems << QStringLiteral("placeholders differ in \"%1\"").arg(form);
        if (accelerators(form) != accelerators(entry.source))
            problems << QStringLiteral("accelerators differ in \"%1\"").arg(form);
    }
    return problems;
}

QString catalogueFile(const char *name)
{
    return QStringLiteral(DRIVEDESK_TRANSLATIONS_DIR "/") + QLatin1String(name);
}

} // namespace

// The German and English catalogues: installTranslations() loads them as both front ends do, the
// window's and the core's texts come out German, counts take the right form, and no entry is
// left unfinished.
class TestTranslations : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(m_german.language().startsWith(QLatin1String("de")));
        QVERIFY(m_english.load(QStringLiteral(":/i18n/drivedesk_en.qm")));
        QVERIFY(!installTranslations(QStringLiteral("xx")));
        QVERIFY(installTranslations(QStringLiteral("de")));
    }

    // The German texts are longer: the toolbar still shows every action at the window's first
    // size, none hidden behind the overflow arrow.
    void theToolbarFitsInGerman()
    {
        MainWindowTest::IsolatedSettings settings;
        MainWindow window(Language::German);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto *bar = window.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
        QVERIFY(bar);
        QVERIFY(bar->actions().first()->text().startsWith(QLatin1String("&Verbinden")));
        const auto *overflow = bar->findChild<QWidget *>(QStringLiteral("qt_toolbar_ext_button"));
        QVERIFY(overflow);
        QVERIFY(!overflow->isVisible());
        for (QAction *action : bar->actions()) {
            if (!action->isSeparator())
                QVERIFY2(bar->widgetForAction(action)->isVisible(), qPrintable(action->text()));
        }
        QVERIFY(bar->widgetForAction(window.findChild<QAction *>(QStringLiteral("monitorAction")))
                    ->isVisible());
    }

    void theConnectionDialogsTabsAreWhole()
    {
        MainWindowTest::IsolatedSettings settings;
        ConnectionDialog dialog;
        auto *tabs = dialog.findChild<QTabWidget *>();
        QVERIFY(tabs);
        tabs->setCurrentIndex(tabs->count() - 1);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        dialog.resize(1, 1); // as narrow as the dialog lets itself be
        QTRY_VERIFY(dialog.width() < 1000);
        QTabBar *bar = tabs->tabBar();
        QCOMPARE(bar->tabText(0), QStringLiteral("&Serielle Schnittstelle"));
        for (int i = 0; i < bar->count(); ++i) {
            const QString text = bar->tabText(i).remove(QLatin1Char('&'));
            QVERIFY2(bar->rect().contains(bar->tabRect(i)), qPrintable(text));
            QVERIFY2(bar->tabRect(i).width() > bar->fontMetrics().horizontalAdvance(text),
                     qPrintable(text));
        }
    }

    void monitorColumnsAreGerman()
    {
        QCOMPARE(TrafficFormat::fieldName(TrafficFormat::Time), QStringLiteral("Zeit"));
        QCOMPARE(TrafficFormat::fieldName(TrafficFormat::Direction), QStringLiteral("Richtung"));
        QCOMPARE(TrafficFormat::fieldName(TrafficFormat::Meaning), QStringLiteral("Bedeutung"));
        QCOMPARE(TrafficFormat::direction(TrafficRecord::Kind::Error), QStringLiteral("Fehler"));
    }

    void parameterColumnsAreGerman()
    {
        ParameterModel model;
        const auto header = [&model](int column) {
            return model.headerData(column, Qt::Horizontal).toString();
        };
        QCOMPARE(header(ParameterModel::DefaultColumn), QStringLiteral("Vorgabewert"));
        QCOMPARE(header(ParameterModel::UnitColumn), QStringLiteral("Einheit"));
        QCOMPARE(header(ParameterModel::AccessColumn), QStringLiteral("Zugriff"));
        QCOMPARE(header(ParameterModel::columnOfSet(3)), QStringLiteral("Satz 3"));
    }

    void editControllerSpeaksGerman()
    {
        DriveClient client(ConnectionSettings{}, everyLink());
        ParameterModel model;
        QUndoStack undoStack;
        EditController controller(&client, &model, &undoStack);
        QSignalSpy messages(&controller, &EditController::message);
        controller.write(0x0203, 0x01, 5);
        QCOMPARE(messages.size(), 1);
        QCOMPARE(messages.first().first().toString(),
                 QStringLiteral("Nicht geschrieben: dieser Umrichter hat keinen Parameter 0203h"));
    }

    // The core's messages reach the window too; their contexts must match the catalogue's.
    void coreMessagesAreGerman()
    {
        QString error;
        QVERIFY(!ParameterId::parse(QString(), QList<GroupAddress>(), &error));
        QCOMPARE(error, QStringLiteral("kein Parameter angegeben"));

        ConnectionSettings settings;
        QVERIFY(!settings.parseTarget(QStringLiteral("tcp:localhost"), &error));
        QCOMPARE(error, QStringLiteral("„localhost“ hat keinen Port: tcp:HOST:PORT angeben"));

        QVERIFY(!ParameterDocument::fromJson("[]", &error));
        QVERIFY2(error.startsWith(QLatin1String("keine DriveDesk-Parameterdatei")),
                 qPrintable(error));
        QVERIFY(!ParameterDocument::fromJson(R"({"format": "drivedesk-parameters", "version": 1})",
                                             &error));
        QCOMPARE(error, QStringLiteral("drive: fehlt (Zeile 1, Spalte 1)"));
    }

    // The drive's refusals, the client's errors and the names of levels and properties: German
    // from the catalogue, the same for the window and the command line.
    void driveAndClientTextsAreGerman()
    {
        Reply refused;
        refused.status = Reply::Status::Refused;
        refused.response.ack = Ack::AddressOrPasswordInvalid;
        refused.attempts = 1;
        QCOMPARE(refused.message(),
                 QStringLiteral("Umrichter lehnt ab: Adresse oder Passwort ungültig"));

        Reply timeout;
        timeout.status = Reply::Status::Timeout;
        timeout.attempts = 3;
        QCOMPARE(timeout.message(),
                 QStringLiteral("keine gültige Antwort vom Umrichter nach 3 Versuchen"));

        QCOMPARE(passwordLevelName(PasswordLevel::DriveMode), QStringLiteral("Drive-Mode"));
        QCOMPARE(GroupProperties(0x0010).describe().last(),
                 QStringLiteral("sichtbar über COMBIVIS"));
        QVERIFY(ParameterProperties(0, 0).describe().contains(
            QStringLiteral("über COMBIVIS nur lesbar")));
    }

    void countsTakeTheirForm()
    {
        const auto german = [this](const char *context, const char *source, int n) {
            return m_german.translate(context, source, nullptr, n);
        };
        QCOMPARE(german("DriveDesk::TelegramMonitor", "%Ln telegram(s)", 1),
                 QStringLiteral("%Ln Telegramm"));
        QCOMPARE(german("DriveDesk::TelegramMonitor", "%Ln telegram(s)", 7),
                 QStringLiteral("%Ln Telegramme"));
        QCOMPARE(QCoreApplication::translate("DriveDesk::ParameterModel", "%1, %n parameter(s)",
                                             nullptr, 1),
                 QStringLiteral("%1, 1 Parameter"));

        const auto english = [this](const char *context, const char *source, int n) {
            return m_english.translate(context, source, nullptr, n);
        };
        QCOMPARE(english("DriveDesk::TelegramMonitor", "%Ln telegram(s)", 1),
                 QStringLiteral("%Ln telegram"));
        QCOMPARE(english("DriveDesk::TelegramMonitor", "%Ln telegram(s)", 2),
                 QStringLiteral("%Ln telegrams"));
        QCOMPARE(english("ParameterDocument", "%n entries; expected 1 (or 8, one for each set)", 0),
                 QStringLiteral("%n entries; expected 1 (or 8, one for each set)"));
        QCOMPARE(english("DriveDesk::TrafficModel", "%n byte(s)", 1), QStringLiteral("%n byte"));

        QCOMPARE(german("ParameterTable", "%n group(s)", 1), QStringLiteral("%n Gruppe"));
        QCOMPARE(german("ParameterTable", "%n group(s)", 16), QStringLiteral("%n Gruppen"));
        QCOMPARE(english("ParameterTable", "%n group(s)", 1), QStringLiteral("%n group"));
        QCOMPARE(german("DriveDesk::ClientWorker", "%n timeout(s)", 2),
                 QStringLiteral("%n Zeitüberschreitungen"));
        QCOMPARE(english("UploadResult", "no value read for set(s) %1", 1),
                 QStringLiteral("no value read for set %1"));
        QCOMPARE(english("UploadResult", "no value read for set(s) %1", 3),
                 QStringLiteral("no value read for sets %1"));
    }

    void cataloguesAreComplete_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("language");
        QTest::newRow("German") << catalogueFile("drivedesk_de.ts") << QStringLiteral("de");
        QTest::newRow("English") << catalogueFile("drivedesk_en.ts") << QStringLiteral("en");
    }

    void cataloguesAreComplete()
    {
        QFETCH(QString, path);
        QFETCH(QString, language);
        const Catalogue catalogue = readCatalogue(path);
        QVERIFY2(catalogue.error.isEmpty(), qPrintable(catalogue.error));
        QVERIFY2(catalogue.language.startsWith(language), qPrintable(catalogue.language));
        QVERIFY(catalogue.entries.size() > 100);

        QStringList problems;
        for (const CatalogueEntry &entry : catalogue.entries) {
            const QStringList found = problemsOf(entry);
            if (!found.isEmpty())
                problems << QStringLiteral("%1 \"%2\": %3")
                                .arg(entry.context, entry.source, found.join(QStringLiteral("; ")));
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    // German belongs in the catalogue: a program source with an umlaut holds a text it misses.
    void noGermanInTheProgramSources()
    {
        static const QRegularExpression umlaut(QStringLiteral("[äöüßÄÖÜ]"));
        QStringList found;
        for (const char *folder : { "core", "ui", "app" }) {
            QDirIterator it(QStringLiteral(DRIVEDESK_SOURCE_DIR "/") + QLatin1String(folder),
                            { QStringLiteral("*.cpp"), QStringLiteral("*.h") }, QDir::Files,
                            QDirIterator::Subdirectories);
            while (it.hasNext()) {
                QFile file(it.next());
                QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
                if (QString::fromUtf8(file.readAll()).contains(umlaut))
                    found << file.fileName();
            }
        }
        QVERIFY2(found.isEmpty(), qPrintable(found.join(QLatin1Char('\n'))));
    }

    void bothCataloguesHoldTheSameTexts()
    {
        QSet<QString> german;
        for (const CatalogueEntry &entry : readCatalogue(catalogueFile("drivedesk_de.ts")).entries)
            german.insert(entry.key());
        QSet<QString> english;
        for (const CatalogueEntry &entry : readCatalogue(catalogueFile("drivedesk_en.ts")).entries)
            english.insert(entry.key());
        QVERIFY2(german == english,
                 qPrintable(QStringList((german - english).values()).join(QLatin1Char('\n'))
                            + QLatin1Char('\n')
                            + QStringList((english - german).values()).join(QLatin1Char('\n'))));
    }

private:
    QTranslator m_german;
    QTranslator m_english;
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
