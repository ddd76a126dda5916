#pragma once

#include "CsvTable.h"
#include "ParameterDatabase.h"

#include <QHash>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk::Sim {

// sim_f5_plaintexts.csv: the simulator's own enumerations, and per parameter id the English
// shortening, German text and display text of the values keb_f5_params.csv names.
class PlaintextTable
{
public:
    static PlaintextTable load(const CsvTable &table, QStringList &problems);

    // The enumeration `key` names; nothing for an unknown key.
    std::optional<Enumeration> enumeration(const QString &key, QStringList &problems) const;
    // The enumeration of parameter `id` from the plaintexts cell of keb_f5_params.csv: the
    // value=text pairs that name one number, completed by this table's rows for `id`.
    Enumeration fromFacts(const QString &id, const QString &factsCell, QStringList &problems) const;
    // Keys (enumerations and parameter ids) no parameter used, to report them.
    QStringList unusedKeys(const QStringList &used) const;

private:
    struct Row
    {
        int line = 0;
        quint32 mask = 0xFFFFFFFF;
        QString descriptionEn;
        QString descriptionDe;
        qint32 value = 0;
        QString display;
        QString textEn;
        QString textDe;
    };

    static Plaintext makePlaintext(qint32 value, const QString &english, const QString &german,
                                   const QString &display, const QString &where,
                                   QStringList &problems);

    QHash<QString, QList<Row>> m_rows;
    QStringList m_keys; // in file order
    QString m_fileName;
};

} // namespace DriveDesk::Sim
