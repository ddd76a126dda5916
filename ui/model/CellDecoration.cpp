#include "CellDecoration.h"

#include <QApplication>
#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QPixmap>
#include <QStyle>

#include <cmath>
#include <numbers>

namespace DriveDesk {

namespace {

constexpr int kIconSize = 16;

// `amount` of `tint` over `base`: a hint of colour that keeps the base's lightness.
QColor blend(const QColor &base, const QColor &tint, qreal amount)
{
    return QColor::fromRgbF(float(base.redF() * (1 - amount) + tint.redF() * amount),
                            float(base.greenF() * (1 - amount) + tint.greenF() * amount),
                            float(base.blueF() * (1 - amount) + tint.blueF() * amount));
}

QPixmap starPixmap()
{
    QPixmap pixmap(kIconSize, kIconSize);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    QPainterPath star;
    const QPointF centre(kIconSize / 2.0, kIconSize / 2.0 + 0.5);
    for (int i = 0; i < 10; ++i) {
        const qreal radius = i % 2 ? 3.0 : 7.5;
        const qreal angle = -std::numbers::pi / 2 + i * std::numbers::pi / 5;
        const QPointF point = centre + QPointF(radius * std::cos(angle), radius * std::sin(angle));
        if (i == 0)
            star.moveTo(point);
        else
            star.lineTo(point);
    }
    star.closeSubpath();
    painter.setPen(QPen(QColor(150, 100, 0), 1));
    painter.setBrush(QColor(255, 190, 0));
    painter.drawPath(star);
    return pixmap;
}

} // namespace

QColor CellDecoration::background(EditState state) const
{
    const QColor base = QGuiApplication::palette().color(QPalette::Base);
    switch (state) {
    case EditState::Pending:
        return blend(base, QColor(255, 176, 0), 0.35);
    case EditState::Written:
    case EditState::Changed: // a file's edit is done as soon as it is made
        return blend(base, QColor(0, 170, 60), 0.30);
    case EditState::Failed:
        return blend(base, QColor(230, 0, 0), 0.35);
    case EditState::Unknown:
        return blend(base, QColor(130, 90, 200), 0.30);
    case EditState::None:
        break;
    }
    return {};
}

QIcon CellDecoration::icon(EditState state) const
{
    QStyle *style = QApplication::style();
    if (!style)
        return {};
    switch (state) {
    case EditState::Pending:
        return style->standardIcon(QStyle::SP_BrowserReload);
    case EditState::Written:
    case EditState::Changed:
        return style->standardIcon(QStyle::SP_DialogApplyButton);
    case EditState::Failed:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    case EditState::Unknown:
        return style->standardIcon(QStyle::SP_MessageBoxQuestion);
    case EditState::None:
        break;
    }
    return {};
}

QIcon CellDecoration::favouriteIcon(bool favourite) const
{
    if (m_star.isNull()) {
        m_star = QIcon(starPixmap());
        QPixmap empty(kIconSize, kIconSize);
        empty.fill(Qt::transparent);
        m_noStar = QIcon(empty);
    }
    return favourite ? m_star : m_noStar;
}

QColor CellDecoration::readOnlyBackground() const
{
    const QPalette palette = QGuiApplication::palette();
    return blend(palette.color(QPalette::Base), palette.color(QPalette::Window), 0.75);
}

QColor CellDecoration::lockedText() const
{
    return QGuiApplication::palette().color(QPalette::Disabled, QPalette::Text);
}

} // namespace DriveDesk
