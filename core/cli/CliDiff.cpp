// drivedesk-cli diff: two parameter files compared, with no drive.
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

void CliRunner::runDiff()
{
    QList<DriveDescription> sides;
    for (const QString &file : std::as_const(m_request.files)) {
        QString error;
        const std::optional<DriveDescription> drive = ParameterDocument::load(file, &error);
        if (!drive)
            return fail(2, error); // it names the file
        sides << *drive;
    }
    const ParameterComparison comparison = compareDescriptions(sides[0], sides[1]);
    if (m_request.format == CliRequest::Format::Json)
        m_out << QString::fromUtf8(toJson(comparison, m_request.files));
    else
        m_out << ParameterTable::differences(comparison, m_request.files[0], m_request.files[1]);
    m_out.flush();
    m_finished = true;
    emit finished(comparison.isEqual() ? 0 : 1);
}

} // namespace DriveDesk
