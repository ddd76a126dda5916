#include "DriveFavourites.h"

#include "model/ParameterModel.h"
#include "parameters/DriveIdentity.h"

#include <QCryptographicHash>
#include <QSettings>

namespace DriveDesk {

namespace {

const QString kFavouritesGroup = QStringLiteral("favourites");

QString favouritesKey(const DriveDescription &drive, const ConnectionSettings *settings)
{
    QString identity = DriveIdentity::summary(drive);
    if (const GroupDescription *info = drive.findGroup(QStringLiteral("In"))) {
        if (const ParameterDescription *serial = drive.find(quint16(info->address + 10))) {
            if (serial->values[0])
                identity += QStringLiteral("/serial %1").arg(*serial->values[0]);
        }
    }
    if (identity.isEmpty() && !settings)
        return {};
    if (identity.isEmpty())
        identity = QStringLiteral("%1/%2").arg(settings->target()).arg(settings->driveAddress);
    return QString::fromLatin1(
        QCryptographicHash::hash(identity.toUtf8(), QCryptographicHash::Sha1).toHex().left(16));
}

} // namespace

void DriveFavourites::restore(const DriveDescription &drive, const ConnectionSettings *settings)
{
    m_key = favouritesKey(drive, settings);
    QSet<quint16> favourites;
    if (!m_key.isEmpty()) {
        const QStringList stored
            = QSettings().value(kFavouritesGroup + QLatin1Char('/') + m_key).toStringList();
        for (const QString &hex : stored) {
            bool ok = false;
            const uint address = hex.toUInt(&ok, 16);
            if (ok && address <= 0xFFFF && m_model->state()->parameter(quint16(address)))
                favourites.insert(quint16(address));
        }
    }
    m_model->setFavourites(favourites);
}

void DriveFavourites::save() const
{
    if (m_key.isEmpty())
        return;
    QStringList addresses;
    const QSet<quint16> favourites = m_model->favourites();
    for (quint16 address : favourites)
        addresses << QString::number(address, 16).rightJustified(4, QLatin1Char('0'));
    addresses.sort();
    QSettings settings;
    const QString key = kFavouritesGroup + QLatin1Char('/') + m_key;
    if (addresses.isEmpty())
        settings.remove(key);
    else
        settings.setValue(key, addresses);
}

} // namespace DriveDesk
