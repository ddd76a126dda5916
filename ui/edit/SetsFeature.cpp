#include "SetsFeature.h"

#include "frame/DriveSession.h"
#include "model/ParameterModel.h"

#include <QLabel>

namespace DriveDesk {

SetsFeature::SetsFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_label = new QLabel;
    m_label->setObjectName(QStringLiteral("parameterSets"));
    m_label->setToolTip(tr("Fr.02: the set the drive works with. Fr.09: the set that "
                                 "indirect addressing reaches."));
    m_label->hide();
    frame.addStatusWidget(m_label);

    ParameterModel *model = frame.model();
    connect(model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
                if (!m_session)
                    return;
                const auto address = topLeft.data(ParameterModel::AddressRole).value<quint16>();
                if (topLeft.row() != bottomRight.row() || address == m_session->activeSetAddress()
                    || address == m_session->setPointerAddress())
                    update();
            });
    connect(model, &QAbstractItemModel::modelReset, this, &SetsFeature::update);
}

void SetsFeature::attach(DriveSession *session)
{
    // What the label shows stays until the model changes: the model keeps the last drive's
    // values until the new one is read.
    m_session = session;
}

void SetsFeature::update()
{
    ParameterModel *model = frame().model();
    const auto valueText = [model](std::optional<quint16> address) {
        if (!address)
            return QString();
        const std::optional<qint32> value = model->state()->value(*address, 0);
        return value ? QString::number(*value)
                     : tr("?");
    };
    // The table marks the active set's column, following every reading of Fr.02.
    model->state()->setActiveSet(m_session ? m_session->activeSet() : -1);
    const QString active = m_session ? valueText(m_session->activeSetAddress()) : QString();
    const QString pointer = m_session ? valueText(m_session->setPointerAddress()) : QString();
    QStringList parts;
    if (!active.isEmpty())
        parts << tr("Active set: %1")
                     .arg(active);
    if (!pointer.isEmpty())
        parts << tr("Set pointer (Fr.09): %1")
                     .arg(pointer);
    m_label->setText(parts.join(QStringLiteral("   ")));
    m_label->setVisible(!parts.isEmpty());
}

} // namespace DriveDesk
