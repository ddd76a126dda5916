#include "DatabaseLoader.h"

#include "CsvTable.h"
#include "DataText.h"
#include "ParameterSpec.h"
#include "PlaintextTable.h"

#include <QHash>
#include <QSet>

// Registers the data compiled into the static library, so that a program linking only
// drivedesk_sim finds it. Outside any namespace, as Q_INIT_RESOURCE requires.
static void initSimulatorResources()
{
    Q_INIT_RESOURCE(drivedesk_sim_data);
}

namespace DriveDesk::Sim {

namespace {

constexpr QLatin1StringView kFactsSuffix(" (per third-party code)");

QString parameterIdText(const QString &group, int number)
{
    return QStringLiteral("%1.%2").arg(group).arg(number, 2, 10, QLatin1Char('0'));
}

// Reads sim_f5_groups.csv into the database; returns group id -> page.
QHash<QString, quint8> loadGroups(const CsvTable &table, ParameterDatabase &db)
{
    QHash<QString, quint8> pages;
    for (const CsvTable::Row &row : table.rows()) {
        const QString where = QStringLiteral("%1:%2").arg(table.fileName()).arg(row.line);
        const QString id = table.cell(row, QStringLiteral("id"));
        bool pageOk = false;
        bool levelOk = false;
        const uint page = table.cell(row, QStringLiteral("page")).toUInt(&pageOk, 16);
        const uint level = table.cell(row, QStringLiteral("level")).toUInt(&levelOk);
        const QString shortcut = table.cell(row, QStringLiteral("shortcut"));
        if (id.size() != 2 || !pageOk || page > 0x7F || !levelOk || level > 7
            || shortcut.size() != 1) {
            db.addProblem(
                QStringLiteral("%1: group needs a 2-letter id, a page 00..7F, a level 0..7 "
                               "and a 1-letter shortcut")
                    .arg(where));
            continue;
        }
        QStringList problems;
        SimGroup group;
        group.page = quint8(page);
        group.id = { id.at(0).toLatin1(), id.at(1).toLatin1() };
        group.shortcut = shortcut.at(0).toLatin1();
        const QString visible = table.cell(row, QStringLiteral("visible"));
        group.properties = quint16(level);
        if (visible.contains(QLatin1Char('d')))
            group.properties |= 1u << 3;
        if (visible.contains(QLatin1Char('c')))
            group.properties |= 1u << 4;
        group.name[0] = lineText(table.cell(row, QStringLiteral("name_en")),
                                 where + QStringLiteral(": name"), problems);
        group.name[1] = lineText(table.cell(row, QStringLiteral("name_de")),
                                 where + QStringLiteral(": name"), problems);
        for (const QString &problem : std::as_const(problems))
            db.addProblem(problem);
        if (pages.contains(id))
            db.addProblem(QStringLiteral("%1: group id %2 is defined twice").arg(where, id));
        db.addGroup(group);
        pages.insert(id, quint8(page));
    }
    return pages;
}

// One parameter: the simulator's row over the facts row (either may be missing).
class ParameterMerge
{
public:
    ParameterMerge(const CsvTable &own, const CsvTable::Row *ownRow, const CsvTable &facts,
                   const CsvTable::Row *factsRow)
        : m_own(own)
        , m_ownRow(ownRow)
        , m_facts(facts)
        , m_factsRow(factsRow)
    { }

    // The simulator's cell, else the facts' cell of the same column.
    QString value(const QString &column) const
    {
        const QString own = m_ownRow ? m_own.cell(*m_ownRow, column) : QString();
        if (!own.isEmpty() || !m_factsRow)
            return own;
        return m_facts.cell(*m_factsRow, column);
    }
    QString own(const QString &column) const
    {
        return m_ownRow ? m_own.cell(*m_ownRow, column) : QString();
    }
    QString fact(const QString &column) const
    {
        return m_factsRow ? m_facts.cell(*m_factsRow, column) : QString();
    }

private:
    const CsvTable &m_own;
    const CsvTable::Row *m_ownRow;
    const CsvTable &m_facts;
    const CsvTable::Row *m_factsRow;
};

// Merges the facts with the simulator's parameter rows into the database.
class Loader
{
public:
    Loader(ParameterDatabase &db, const PlaintextTable &plaintexts, const CsvTable &facts,
           const CsvTable &own, const QHash<QString, quint8> &pages)
        : m_db(db)
        , m_plaintexts(plaintexts)
        , m_facts(facts)
        , m_own(own)
        , m_pages(pages)
    { }

    void run();
    QStringList usedPlaintextKeys() const { return m_usedKeys; }

private:
    void addParameter(const QString &group, int number, const CsvTable::Row *ownRow,
                      const CsvTable::Row *factsRow);
    int enumerationFor(const QString &id, const QString &reference, const QString &factsCell);
    void problem(const QString &text) { m_db.addProblem(text); }

    ParameterDatabase &m_db;
    const PlaintextTable &m_plaintexts;
    const CsvTable &m_facts;
    const CsvTable &m_own;
    const QHash<QString, quint8> &m_pages;
    QHash<QString, int> m_enumerationOf; // parameter id -> enumeration
    QStringList m_usedKeys;
};

void Loader::run()
{
    QHash<QString, const CsvTable::Row *> factsById;
    QStringList factsOrder;
    for (const CsvTable::Row &row : m_facts.rows()) {
        const QString group = m_facts.cell(row, QStringLiteral("group"));
        const int number = m_facts.cell(row, QStringLiteral("number")).toInt();
        const QString id = parameterIdText(group, number);
        if (!m_pages.contains(group)) {
            m_db.addNote(QStringLiteral("%1 (%2) left out: group %3 is not an F5 inverter group "
                                        "(operator, CP mode, elevator firmware or G6)")
                             .arg(id, m_facts.cell(row, QStringLiteral("name_en")), group));
            continue;
        }
        factsById.insert(id, &row);
        factsOrder << id;
    }
    QSet<QString> done;
    for (const CsvTable::Row &row : m_own.rows()) {
        const QString group = m_own.cell(row, QStringLiteral("group"));
        bool ok = false;
        const int number = m_own.cell(row, QStringLiteral("number")).toInt(&ok);
        if (!m_pages.contains(group) || !ok || number < 0 || number > 255) {
            problem(QStringLiteral("%1:%2: unknown group \"%3\" or number out of 0..255")
                        .arg(m_own.fileName())
                        .arg(row.line)
                        .arg(group));
            continue;
        }
        const QString id = parameterIdText(group, number);
        addParameter(group, number, &row, factsById.value(id));
        done.insert(id);
    }
    for (const QString &id : std::as_const(factsOrder)) {
        if (done.contains(id))
            continue;
        const CsvTable::Row *row = factsById.value(id);
        addParameter(m_facts.cell(*row, QStringLiteral("group")),
                     m_facts.cell(*row, QStringLiteral("number")).toInt(), nullptr, row);
    }
}

int Loader::enumerationFor(const QString &id, const QString &reference, const QString &factsCell)
{
    if (reference.isEmpty())
        return -1;
    QStringList problems;
    if (reference == QLatin1String("facts")) {
        m_usedKeys << id;
        const Enumeration enumeration = m_plaintexts.fromFacts(id, factsCell, problems);
        for (const QString &p : std::as_const(problems))
            problem(p);
        return m_db.addEnumeration(QString(), enumeration);
    }
    if (reference.startsWith(QLatin1Char('@'))) {
        const int index = m_enumerationOf.value(reference.mid(1), -1);
        if (index < 0)
            problem(QStringLiteral("%1: %2 has no plaintexts (yet) to share")
                        .arg(id, reference.mid(1)));
        return index;
    }
    const int known = m_db.enumerationIndex(reference);
    if (known >= 0)
        return known;
    const std::optional<Enumeration> enumeration = m_plaintexts.enumeration(reference, problems);
    for (const QString &p : std::as_const(problems))
        problem(p);
    if (!enumeration) {
        problem(QStringLiteral("%1: unknown plaintexts \"%2\"").arg(id, reference));
        return -1;
    }
    m_usedKeys << reference;
    return m_db.addEnumeration(reference, *enumeration);
}

void Loader::addParameter(const QString &group, int number, const CsvTable::Row *ownRow,
                          const CsvTable::Row *factsRow)
{
    const ParameterMerge m(m_own, ownRow, m_facts, factsRow);
    ParameterSpec spec;
    spec.id = parameterIdText(group, number);
    const QString &id = spec.id;
    spec.address = quint16(m_pages.value(group) << 8 | number);
    if (factsRow) {
        bool ok = false;
        const uint listed = m.fact(QStringLiteral("address_hex")).toUInt(&ok, 16);
        if (!ok || listed != spec.address)
            problem(QStringLiteral("%1: keb_f5_params.csv gives address %2, the group map %3h")
                        .arg(id, m.fact(QStringLiteral("address_hex")))
                        .arg(spec.address, 4, 16, QLatin1Char('0')));
    }
    spec.nameEn = m.value(QStringLiteral("name_en"));
    if (spec.nameEn.endsWith(kFactsSuffix))
        spec.nameEn.chop(kFactsSuffix.size());
    spec.nameDe = m.value(QStringLiteral("name_de"));

    QChar bad;
    std::optional<ParameterFlags> flags = parseFlags(m.own(QStringLiteral("flags")), &bad);
    if (!flags) {
        problem(QStringLiteral("%1: unknown flag '%2'").arg(id, QString(bad)));
        flags = ParameterFlags {};
    }
    if (m.fact(QStringLiteral("set_programmable")) == QLatin1String("yes"))
        flags->setProgrammable = true;
    const QString unit = m.value(QStringLiteral("unit"));
    if (unit == QLatin1String("hex"))
        flags->hex = true;
    spec.flags = *flags;
    spec.unit = unit;
    spec.decimals = m.value(QStringLiteral("decimals")).toInt();

    const QString scale = m.own(QStringLiteral("scale"));
    if (!scale.isEmpty()) {
        const QStringList parts = scale.split(QLatin1Char(':'));
        bool ok = parts.size() == 3;
        qint32 numbers[3] = {};
        for (int i = 0; ok && i < 3; ++i) {
            numbers[i] = parts.at(i).toInt(&ok);
            ok = ok && numbers[i] >= -32768 && numbers[i] <= 32767;
        }
        if (ok) {
            spec.explicitScale = true;
            spec.divisor = qint16(numbers[0]);
            spec.multiplier = qint16(numbers[1]);
            spec.offset = qint16(numbers[2]);
        } else {
            problem(
                QStringLiteral("%1: scale \"%2\" is not divisor:multiplier:offset").arg(id, scale));
        }
    }
    const int decimals = spec.explicitScale ? 0 : spec.decimals;
    // keb_f5_params.csv writes numbers as its sources did: In.25 "65535" is decimal though the
    // parameter shows hex, Sy.16 "7FFF" is hex without a suffix. So a facts cell is hex only
    // when it cannot be decimal; the simulator's own cells follow the h flag.
    const auto limitValue = [&](const QString &column) {
        const QString own = m.own(column);
        const QString text = own.isEmpty() ? m.fact(column) : own;
        const bool hex = own.isEmpty() ? !isDecimalNumber(text) : spec.flags.hex;
        const std::optional<qint32> value = parseNumber(text, decimals, hex);
        if (!text.isEmpty() && !value)
            problem(QStringLiteral("%1: %2 \"%3\" is not a number").arg(id, column, text));
        return value;
    };
    const std::optional<qint32> minimum = limitValue(QStringLiteral("min"));
    const std::optional<qint32> maximum = limitValue(QStringLiteral("max"));
    if (!minimum || !maximum)
        problem(QStringLiteral("%1: no limits").arg(id));
    spec.minimum = minimum.value_or(0);
    spec.maximum = maximum.value_or(0);
    const std::optional<qint32> defaultValue = limitValue(QStringLiteral("default"));
    spec.defaultValue
        = defaultValue.value_or(spec.minimum > 0 || spec.maximum < 0 ? spec.minimum : 0);

    const auto level = [&](const QString &column) {
        const QString text = m.own(column);
        if (text.isEmpty())
            return 3;
        bool ok = false;
        const int value = text.toInt(&ok);
        if (!ok || value < 0 || value > 7) {
            problem(QStringLiteral("%1: password level \"%2\" is not 0..7").arg(id, text));
            return 3;
        }
        return value;
    };
    spec.readLevel = level(QStringLiteral("read"));
    spec.writeLevel = level(QStringLiteral("write"));

    const QString signalName = m.own(QStringLiteral("signal"));
    const std::optional<LiveSignal> signal = liveSignalFromName(signalName);
    if (!signal)
        problem(QStringLiteral("%1: unknown signal \"%2\"").arg(id, signalName));
    spec.signal = signal.value_or(LiveSignal::None);

    const QString initial = m.own(QStringLiteral("initial"));
    if (!initial.isEmpty()) {
        for (const QString &part : initial.split(QLatin1Char('|'))) {
            const std::optional<qint32> value = parseNumber(part, decimals, spec.flags.hex);
            if (!value)
                problem(QStringLiteral("%1: initial value \"%2\" is not a number").arg(id, part));
            spec.initial << value.value_or(spec.defaultValue);
        }
    }
    spec.enumeration = enumerationFor(id, m.own(QStringLiteral("plaintexts")),
                                      m.fact(QStringLiteral("plaintexts")));
    spec.systemParameter = group == QLatin1String("Sy");
    spec.encoderParameter = group == QLatin1String("Ec");

    QStringList problems;
    const SimParameter parameter = buildParameter(spec, problems);
    for (const QString &p : std::as_const(problems))
        problem(p);
    m_db.addParameter(parameter);
    if (spec.enumeration >= 0)
        m_enumerationOf.insert(id, spec.enumeration);
}

} // namespace

QString resourceDirectory()
{
    static const bool registered = (initSimulatorResources(), true);
    Q_UNUSED(registered);
    return QStringLiteral(":/drivedesk/sim");
}

std::shared_ptr<ParameterDatabase> loadDatabase(const QString &directory)
{
    auto db = std::make_shared<ParameterDatabase>();
    const auto read = [&](const char *name) {
        CsvTable table = CsvTable::read(directory + QLatin1Char('/') + QLatin1StringView(name));
        for (const QString &problem : table.problems())
            db->addProblem(problem);
        return table;
    };
    const CsvTable groups = read("sim_f5_groups.csv");
    const CsvTable facts = read("keb_f5_params.csv");
    const CsvTable own = read("sim_f5_parameters.csv");
    const CsvTable texts = read("sim_f5_plaintexts.csv");

    const QHash<QString, quint8> pages = loadGroups(groups, *db);
    QStringList problems;
    const PlaintextTable plaintexts = PlaintextTable::load(texts, problems);
    for (const QString &problem : std::as_const(problems))
        db->addProblem(problem);
    Loader loader(*db, plaintexts, facts, own, pages);
    loader.run();
    for (const QString &key : plaintexts.unusedKeys(loader.usedPlaintextKeys()))
        db->addProblem(QStringLiteral("%1: plaintexts \"%2\" are used by no parameter")
                           .arg(texts.fileName(), key));
    db->finish();
    return db;
}

std::shared_ptr<const ParameterDatabase> standardDatabase()
{
    static const std::shared_ptr<const ParameterDatabase> database = [] {
        std::shared_ptr<ParameterDatabase> db = loadDatabase(resourceDirectory());
        for (const QString &problem : db->problems())
            qWarning("simulated drive data: %s", qPrintable(problem));
        return db;
    }();
    return database;
}

} // namespace DriveDesk::Sim
