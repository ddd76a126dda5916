// The man pages (packaging/man) name every option, command and exit status that the programs'
// --help names, their bash completions offer those options, commands and values, and --version
// prints the project's version.
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

namespace {

const QString kBinaryDir = QStringLiteral(DRIVEDESK_BINARY_DIR);
const QString kPackagingDir = QStringLiteral(DRIVEDESK_PACKAGING_DIR);

QString programPath(const QString &program)
{
    const QString folder = program == QLatin1String("drivedesk")       ? QStringLiteral("gui")
                           : program == QLatin1String("drivedesk-cli") ? QStringLiteral("cli")
                                                                        : QStringLiteral("sim");
    return kBinaryDir + QStringLiteral("/app/%1/%2").arg(folder, program);
}

QString run(const QString &program, const QStringList &arguments)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    process.setProcessEnvironment(environment);
    process.start(programPath(program), arguments);
    if (!process.waitForFinished(30000)) {
        process.kill();
        process.waitForFinished();
        return QStringLiteral("%1 did not finish").arg(program);
    }
    if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0)
        return QStringLiteral("%1 exited with %2: %3")
            .arg(program)
            .arg(process.exitCode())
            .arg(QString::fromUtf8(process.readAllStandardError()));
    return QString::fromUtf8(process.readAllStandardOutput());
}

// The man page as a reader sees its words: no comments, no font changes, '\-' as '-'.
QString manPageText(const QString &program)
{
    QFile file(kPackagingDir + QStringLiteral("/man/%1.1").arg(program));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QStringList lines;
    for (const QString &line : QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'))) {
        if (!line.startsWith(QLatin1String(".\\\"")) && !line.startsWith(QLatin1String("'\\\"")))
            lines << line;
    }
    QString text = lines.join(QLatin1Char('\n'));
    static const QRegularExpression font(QStringLiteral("\\\\f[BIRP]"));
    text.remove(font);
    text.replace(QLatin1String("\\-"), QLatin1String("-"));
    return text;
}

// "--baud", "-h": each option the help names, wherever it names it.
QStringList optionsIn(const QString &help)
{
    static const QRegularExpression option(
        QStringLiteral("(?<![\\w-])(--[a-z0-9][a-z0-9-]*|-[a-zA-Z])(?![\\w-])"));
    QStringList options;
    for (const QRegularExpressionMatch &match : option.globalMatch(help)) {
        if (!options.contains(match.captured(1)))
            options << match.captured(1);
    }
    return options;
}

// The first word of each entry of a section like "Commands:" or "Exit status:", entries
// indented by two spaces, up to the next unindented line.
QStringList entriesOf(const QString &help, const QString &section)
{
    QStringList entries;
    const QStringList lines = help.split(QLatin1Char('\n'));
    const qsizetype start = lines.indexOf(section);
    static const QRegularExpression entry(QStringLiteral("^  (\\S+)"));
    for (qsizetype i = start + 1; start >= 0 && i < lines.size(); ++i) {
        if (!lines[i].startsWith(QLatin1Char(' ')))
            break;
        const QRegularExpressionMatch match = entry.match(lines[i]);
        if (match.hasMatch() && !entries.contains(match.captured(1)))
            entries << match.captured(1);
    }
    return entries;
}

bool mentions(const QString &text, const QString &word)
{
    return QRegularExpression(QStringLiteral("(?<![\\w-])%1(?![\\w-])")
                                  .arg(QRegularExpression::escape(word)))
        .match(text)
        .hasMatch();
}

// The tags of a tagged list: each line after ".TP", e.g. ".BR -h \", \" --help".
QString tagsOf(const QString &text)
{
    QStringList tags;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (qsizetype i = 1; i < lines.size(); ++i) {
        if (lines[i - 1] == QLatin1String(".TP"))
            tags << lines[i];
    }
    return tags.join(QLatin1Char('\n'));
}

// A tag that starts with the word, e.g. ".BI read \" PARAM\"" for "read".
bool hasEntry(const QString &tags, const QString &word)
{
    return QRegularExpression(QStringLiteral("^\\.B[IR]? \"?%1\\b")
                                  .arg(QRegularExpression::escape(word)),
                              QRegularExpression::MultilineOption)
        .match(tags)
        .hasMatch();
}

} // namespace

class tst_ManPages : public QObject
{
    Q_OBJECT

private slots:
    void coversHelp_data()
    {
        QTest::addColumn<QString>("program");
        QTest::newRow("drivedesk") << QStringLiteral("drivedesk");
        QTest::newRow("drivedesk-cli") << QStringLiteral("drivedesk-cli");
        QTest::newRow("drivedesk-sim") << QStringLiteral("drivedesk-sim");
    }

    void coversHelp()
    {
        QFETCH(QString, program);
        const QString help = run(program, {QStringLiteral("--help")});
        const QStringList options = optionsIn(help);
        QVERIFY2(options.contains(QStringLiteral("--connect"))
                     || options.contains(QStringLiteral("--listen")),
                 qPrintable(help));
        const QString page = manPageText(program);
        QVERIFY2(!page.isEmpty(), qPrintable(program + QStringLiteral(".1 is missing")));

        const QString tags = tagsOf(page);
        QStringList missing;
        for (const QString &option : options) {
            if (!mentions(tags, option))
                missing << option;
        }
        for (const QString &command : entriesOf(help, QStringLiteral("Commands:"))) {
            if (!hasEntry(tags, command))
                missing << command;
        }
        const QString exitTags = tagsOf(page.mid(page.indexOf(QLatin1String(".SH EXIT STATUS"))));
        for (const QString &status : entriesOf(help, QStringLiteral("Exit status:"))) {
            if (!page.contains(QLatin1String(".SH EXIT STATUS")) || !hasEntry(exitTags, status))
                missing << QStringLiteral("exit status ") + status;
        }
        QVERIFY2(missing.isEmpty(),
                 qPrintable(QStringLiteral("%1 --help names what %1.1 does not describe: %2")
                                .arg(program, missing.join(QStringLiteral(", ")))));
        QVERIFY2(mentions(page, QStringLiteral("--version")), qPrintable(program));
    }

    void completionCoversHelp_data() { coversHelp_data(); }

    void completionCoversHelp()
    {
        QFETCH(QString, program);
        const QString help = run(program, {QStringLiteral("--help")});
        QFile file(kPackagingDir + QStringLiteral("/completion/") + program);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString completion = QString::fromUtf8(file.readAll());

        QStringList expected = optionsIn(help).filter(QRegularExpression(QStringLiteral("^--")));
        expected += entriesOf(help, QStringLiteral("Commands:"));
        // The values the help lists: "--language en|de", "--format json|table|csv", the protocols.
        static const QRegularExpression choices(
            QStringLiteral("--[a-z-]+ ([a-z0-9]+(\\|[a-z0-9]+)+)"));
        for (const QRegularExpressionMatch &match : choices.globalMatch(help))
            expected += match.captured(1).split(QLatin1Char('|'));
        static const QRegularExpression protocol(QStringLiteral("\\b(hsp5|din66019\\w*)\\b"));
        for (const QRegularExpressionMatch &match : protocol.globalMatch(help))
            expected << match.captured(1);
        QVERIFY(expected.contains(QStringLiteral("din66019ii")));

        QStringList missing;
        for (const QString &word : std::as_const(expected)) {
            if (!mentions(completion, word) && !missing.contains(word))
                missing << word;
        }
        QVERIFY2(missing.isEmpty(),
                 qPrintable(QStringLiteral("%1 --help names what its completion does not offer: "
                                           "%2")
                                .arg(program, missing.join(QStringLiteral(", ")))));
    }

    void printsTheProjectVersion_data() { coversHelp_data(); }

    void printsTheProjectVersion()
    {
        QFETCH(QString, program);
        QCOMPARE(run(program, {QStringLiteral("--version")}),
                 QStringLiteral("%1 %2\n").arg(program, QStringLiteral(DRIVEDESK_VERSION)));
    }

    // On a machine without a display (a server, a terminal over ssh) --help still answers:
    // the usage needs no window system, and Qt would abort reaching for one.
    void theWindowsHelpNeedsNoDisplay()
    {
        QProcess process;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        for (const char *name : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"})
            environment.remove(QString::fromLatin1(name));
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
        process.setProcessEnvironment(environment);
        process.start(programPath(QStringLiteral("drivedesk")), {QStringLiteral("--help")});
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 0);
        QVERIFY(QString::fromUtf8(process.readAllStandardOutput()).contains(QStringLiteral("--connect")));
    }
};

QTEST_GUILESS_MAIN(tst_ManPages)
#include "tst_manpages.moc"
