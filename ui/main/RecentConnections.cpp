#include "RecentConnections.h"

#include "protocol/Codec.h"

#include <QCoreApplication>
#include <QSettings>

namespace DriveDesk {

namespace {

const QString kGroup = QStringLiteral("connections");
const QString kArray = QStringLiteral("recent");

void write(QSettings &store, const ConnectionSettings &settings)
{
    store.setValue(QStringLiteral("target"), settings.target());
    store.setValue(QStringLiteral("protocol"), protocolName(settings.protocol));
    store.setValue(QStringLiteral("address"), settings.driveAddress);
    store.setValue(QStringLiteral("baud"), settings.baudRate);
    store.setValue(QStringLiteral("automaticBaud"), settings.automaticBaudRate);
    store.setValue(QStringLiteral("hsp5Extensions"), settings.hsp5Extensions);
}

std::optional<ConnectionSettings> read(const QSettings &store)
{
    ConnectionSettings settings;
    if (!settings.parseTarget(store.value(QStringLiteral("target")).toString(), nullptr))
        return std::nullopt;
    const auto protocol = protocolFromName(store.value(QStringLiteral("protocol")).toString());
    if (!protocol)
        return std::nullopt;
    settings.protocol = *protocol;
    bool ok = false;
    const int address = store.value(QStringLiteral("address")).toInt(&ok);
    if (!ok || address < 0 || address > 239)
        return std::nullopt;
    settings.driveAddress = address;
    const int baud = store.value(QStringLiteral("baud")).toInt(&ok);
    if (ok && baud > 0)
        settings.baudRate = baud;
    // A rate found by the search is searched for again: the drive may have been set to another.
    settings.automaticBaudRate = settings.kind == ConnectionSettings::Kind::Serial
                                 && store.value(QStringLiteral("automaticBaud")).toBool();
    settings.simulation.driveAddresses = { settings.driveAddress };
    settings.simulation.baudRate = settings.baudRate;
    settings.hsp5Extensions = settings.protocol == Protocol::Hsp5
                              && store.value(QStringLiteral("hsp5Extensions")).toBool();
    settings.simulation.hsp5Extensions = settings.hsp5Extensions;
    return settings;
}

} // namespace

QList<ConnectionSettings> RecentConnections::load()
{
    QSettings store;
    store.beginGroup(kGroup);
    QList<ConnectionSettings> list;
    const int size = store.beginReadArray(kArray);
    for (int i = 0; i < size && list.size() < kMaximum; ++i) {
        store.setArrayIndex(i);
        // An entry another version wrote in a form this one cannot read is left out.
        if (const auto settings = read(store))
            list << *settings;
    }
    store.endArray();
    return list;
}

void RecentConnections::remember(const ConnectionSettings &settings)
{
    QList<ConnectionSettings> list = load();
    list.removeIf([&](const ConnectionSettings &s) { return sameConnection(s, settings); });
    list.prepend(settings);
    while (list.size() > kMaximum)
        list.removeLast();

    QSettings store;
    store.beginGroup(kGroup);
    store.remove(kArray);
    store.beginWriteArray(kArray, int(list.size()));
    for (int i = 0; i < list.size(); ++i) {
        store.setArrayIndex(i);
        write(store, list[i]);
    }
    store.endArray();
}

ConnectionSettings RecentConnections::last()
{
    const QList<ConnectionSettings> list = load();
    return list.isEmpty() ? ConnectionSettings {} : list.constFirst();
}

bool RecentConnections::sameConnection(const ConnectionSettings &a, const ConnectionSettings &b)
{
    return a.target() == b.target() && a.protocol == b.protocol && a.driveAddress == b.driveAddress
        && (a.kind != ConnectionSettings::Kind::Serial
            || (a.automaticBaudRate == b.automaticBaudRate
                && (a.automaticBaudRate || a.baudRate == b.baudRate)));
}

QString RecentConnections::describe(const ConnectionSettings &settings)
{
    // The simulated drive on a DIN bus answers at one address: name it.
    if (settings.kind == ConnectionSettings::Kind::Simulated && settings.protocol != Protocol::Hsp5)
        return QCoreApplication::translate("DriveDesk::RecentConnections", "%1, address %2")
            .arg(settings.displayName())
            .arg(settings.driveAddress);
    return settings.displayName();
}

} // namespace DriveDesk
