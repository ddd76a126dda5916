#include "DriveInfoDialog.h"

#include "RecentConnections.h"

#include "parameters/DriveIdentity.h"
#include "protocol/Codec.h"

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace DriveDesk {

QList<DriveInfoDialog::Line> DriveInfoDialog::lines(const DriveDescription &drive,
                                                    const ConnectionSettings &settings)
{
    QList<Line> lines;
    for (const DriveIdentity::Line &line : DriveIdentity::lines(drive))
        lines.append({ line.label, line.value });
    lines.append({ tr("Connection"), RecentConnections::describe(settings) });
    lines.append({ tr("Protocol"), protocolName(settings.protocol).toUpper() });
    if (settings.protocol != Protocol::Hsp5)
        lines.append({ tr("Drive address"), QString::number(settings.driveAddress) });
    lines.append({ tr("Parameter groups"), QString::number(drive.groups.size()) });
    lines.append({ tr("Parameters"), QString::number(drive.parameterCount()) });
    lines.append({ tr("Metadata"),
                   drive.metadataFromCache ? tr("from the metadata cache of this kind of drive")
                                           : tr("read from the drive") });
    if (!drive.incompleteReason.isEmpty())
        lines.append({ tr("Scan incomplete"), drive.incompleteReason });
    return lines;
}

DriveInfoDialog::DriveInfoDialog(const DriveDescription &drive, const ConnectionSettings &settings,
                                 QWidget *parent)
    : QDialog(parent)
    , m_lines(lines(drive, settings))
{
    setWindowTitle(tr("Drive information"));
    m_text = new QTextBrowser;
    m_text->setObjectName(QStringLiteral("driveInformation"));
    m_text->setOpenLinks(false);
    QString html = QStringLiteral("<table cellspacing=\"4\">");
    for (const Line &line : std::as_const(m_lines)) {
        html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(line.label.toHtmlEscaped(), line.value.toHtmlEscaped());
    }
    html += QStringLiteral("</table>");
    m_text->setHtml(html);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton *copy = buttons->addButton(tr("&Copy"), QDialogButtonBox::ActionRole);
    copy->setObjectName(QStringLiteral("copyInformation"));
    connect(copy, &QPushButton::clicked, this,
            [this] { QApplication::clipboard()->setText(plainText()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_text);
    layout->addWidget(buttons);
    resize(fontMetrics().averageCharWidth() * 90, fontMetrics().height() * 24);
}

QString DriveInfoDialog::plainText() const
{
    QStringList text;
    for (const Line &line : m_lines)
        text << QStringLiteral("%1: %2").arg(line.label, line.value);
    return text.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace DriveDesk
