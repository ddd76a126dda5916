// drivedesk-cli diff: two sides compared, each a parameter file, the drive or the defaults.
#include "CliRunner.h"

#include "cli/ParameterTable.h"
#include "parameters/ParameterComparison.h"
#include "parameters/ParameterDocument.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace DriveDesk {

namespace {

QString kindKey(ParameterDifference::Kind kind)
{
    switch (kind) {
    case ParameterDifference::Kind::Different:
        return QStringLiteral("different");
    case ParameterDifference::Kind::OnlyInA:
        return QStringLiteral("onlyInA");
    case ParameterDifference::Kind::OnlyInB:
        return QStringLiteral("onlyInB");
    }
    return {};
}

QByteArray toJson(const ParameterComparison &comparison, const QStringList &files)
{
    QJsonArray differences;
    for (const ParameterDifference &d : comparison.differences) {
        QJsonObject entry{ { QStringLiteral("id"), d.id },
                           { QStringLiteral("address"), int(d.address) },
                           { QStringLiteral("name"), d.name },
                           { QStringLiteral("state"), kindKey(d.kind) },
                           { QStringLiteral("a"), d.a },
                           { QStringLiteral("b"), d.b } };
        if (d.set >= 0)
            entry.insert(QStringLiteral("set"), d.set);
        differences.append(entry);
    }
    const QJsonObject root{ { QStringLiteral("a"), files.value(0) },
                            { QStringLiteral("b"), files.value(1) },
                            { QStringLiteral("compared"), comparison.compared },
                            { QStringLiteral("differences"), differences } };
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

} // namespace

bool CliRunner::loadFiles()
{
    if (m_request.command != CliRequest::Command::Diff
        && m_request.command != CliRequest::Command::Download)
        return true;
    for (const QString &file : std::as_const(m_request.files)) {
        if (file == QLatin1String("drive") || file == QLatin1String("defaults"))
            continue;
        QString error;
        const std::optional<DriveDescription> drive = ParameterDocument::load(file, &error);
        if (!drive) {
            fail(2, error); // it names the file
            return false;
        }
        m_files << *drive;
    }
    return true;
}

// The drive side is what an upload would write: the parameters of a parameter list.
void CliRunner::runDiff()
{
    if (!m_request.files.contains(QStringLiteral("drive"))) {
        const DriveDescription &first = m_files.constFirst();
        return printDiff(first, m_files.value(1, first));
    }
    ScanOptions options;
    options.values = true;
    options.parameterList = true;
    scan(options, [this](const DriveDescription &drive) {
        if (!drive.incompleteReason.isEmpty())
            return fail(1, tr("could not read the drive: %1").arg(drive.incompleteReason));
        const bool driveFirst = m_request.files.constFirst() == QLatin1String("drive");
        const DriveDescription other = m_files.value(0, drive);
        printDiff(driveFirst ? drive : other, driveFirst ? other : drive);
    });
}

void CliRunner::printDiff(const DriveDescription &a, const DriveDescription &b)
{
    const bool defaultsFirst = m_request.files[0] == QLatin1String("defaults");
    const bool withDefaults = defaultsFirst || m_request.files[1] == QLatin1String("defaults");
    const ParameterComparison comparison = withDefaults ? compareWithDefaults(a, defaultsFirst)
                                                        : compareDescriptions(a, b);
    if (m_request.format == CliRequest::Format::Json)
        m_out << QString::fromUtf8(toJson(comparison, m_request.files));
    else
        m_out << ParameterTable::differences(comparison, m_request.files[0], m_request.files[1]);
    m_out.flush();
    m_finished = true;
    emit finished(comparison.isEqual() ? 0 : 1);
}

} // namespace DriveDesk
