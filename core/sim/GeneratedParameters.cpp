#include "GeneratedParameters.h"

#include "F5Addresses.h"
#include "ParameterSpec.h"

#include <algorithm>

namespace DriveDesk::Sim {

namespace {

quint64 mix(quint64 x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Kinds of generated parameter, so that every kind of metadata shows up in a large scan.
ParameterSpec generatedSpec(quint16 address, const QString &id, quint64 random, int onOff)
{
    ParameterSpec spec;
    spec.address = address;
    spec.id = id;
    spec.nameEn = QStringLiteral("Generated %1").arg(id);
    spec.nameDe = QStringLiteral("Erzeugt %1").arg(id);
    const qint32 spread = qint32(random >> 40) % 1000;
    switch (random % 8) {
    case 0:
        spec.maximum = 100 + spread;
        spec.defaultValue = spread / 10;
        break;
    case 1:
        spec.minimum = -1000 - spread;
        spec.maximum = 1000 + spread;
        spec.unit = QStringLiteral("rpm");
        break;
    case 2:
        spec.maximum = 100000;
        spec.defaultValue = spread * 10;
        spec.decimals = 2;
        spec.unit = QStringLiteral("s");
        break;
    case 3:
        spec.maximum = 1000;
        spec.defaultValue = 500;
        spec.decimals = 1;
        spec.unit = QStringLiteral("%");
        spec.flags.setProgrammable = true;
        break;
    case 4:
        spec.maximum = 1;
        spec.enumeration = onOff;
        break;
    case 5:
        spec.maximum = 65535;
        spec.defaultValue = spread;
        spec.flags.readOnly = true;
        break;
    case 6:
        spec.maximum = 0xFFFF;
        spec.flags.hex = true;
        break;
    default:
        spec.minimum = -400;
        spec.maximum = 400;
        spec.decimals = 1;
        spec.unit = QStringLiteral("Hz");
        spec.flags.setProgrammable = true;
        break;
    }
    return spec;
}

} // namespace

void addGeneratedParameters(ParameterDatabase &db, int total, quint32 seed)
{
    const int standard = int(db.parameters().size());
    const int capacity = (kGeneratedLastPage - kGeneratedFirstPage + 1) * kGeneratedPerGroup;
    const int generated = std::min(total - standard, capacity);
    int missing = generated;
    if (total - standard > capacity)
        db.addNote(QStringLiteral("%1 parameters asked for, %2 generated at most")
                       .arg(total)
                       .arg(standard + capacity));
    const int onOff = db.enumerationIndex(QStringLiteral("onoff"));
    QStringList problems;
    for (int page = kGeneratedFirstPage; missing > 0 && page <= kGeneratedLastPage; ++page) {
        const int ordinal = page - kGeneratedFirstPage;
        SimGroup group;
        group.page = quint8(page);
        group.id = { char('W' + ordinal / 26), char('a' + ordinal % 26) };
        group.shortcut = 'x';
        group.properties = quint16(3 | 1u << 3 | 1u << 4); // Application, visible everywhere
        group.name[0] = QStringLiteral("Generated group %1").arg(ordinal + 1).toLatin1();
        group.name[1] = QStringLiteral("Erzeugte Gruppe %1").arg(ordinal + 1).toLatin1();
        db.addGroup(group);
        const QString groupId = QString::fromLatin1(group.id.data(), 2);
        for (int number = 0; missing > 0 && number < kGeneratedPerGroup; ++number, --missing) {
            const auto address = quint16(page << 8 | number);
            const QString id
                = QStringLiteral("%1.%2").arg(groupId).arg(number, 2, 10, QLatin1Char('0'));
            const quint64 random = mix(quint64(seed) << 16 | address);
            db.addParameter(buildParameter(generatedSpec(address, id, random, onOff), problems));
        }
    }
    // A drive with other parameters runs other software: its version (In.06, two decimals)
    // tells it apart from the standard drive and from padded drives of other sizes, as the
    // metadata cache expects of real drives.
    if (const SimParameter *version = db.find(F5::kSoftwareVersion))
        db.setDefaultValue(F5::kSoftwareVersion,
                           std::min(version->defaultValue + generated, version->maximum));
    else
        problems << QStringLiteral("the software version In.06 is missing");
    for (const QString &problem : std::as_const(problems))
        db.addProblem(problem);
    db.finish();
}

} // namespace DriveDesk::Sim
