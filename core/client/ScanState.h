#pragma once

#include "parameters/DriveDescription.h"
#include "protocol/Language.h"

#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace DriveDesk {

// A COMBIVIS plaintext definition while its texts are still arriving.
struct ScanDefinition {
    std::optional<PlaintextDefinition> definition;      // once service 12 answered
    std::vector<std::optional<PlaintextEntry>> entries; // by subindex, as service 9 answers
};

// The texts of one COMBIVIS plaintext index with its number of definitions. Services 12 and 9
// address them by index, not by parameter: they are read once, however many parameters share
// them (every on/off parameter of a drive, say).
struct ScanPlaintextTable {
    std::vector<ScanDefinition> definitions;         // by definition index
    QStringList errors;                              // one line per failed read
    int unanswered = 0;                              // of those, reads with no valid answer
    int pending = 0;                                 // requests not yet answered
    std::vector<std::pair<quint8, quint8>> users;    // (page, number) of the parameters
};

// A parameter while its metadata and values are still arriving.
struct ScanParameter {
    ParameterDescription description;
    QStringList errors;                      // one line per failed read
    int metadataErrors = 0;                  // of those, reads of metadata (not of values)
    // Of those, reads that got no valid answer (unanswered, never agreeing, implausible, not
    // decodable) rather than the drive's refusal: the line's fault, so the parameter is not read.
    int unanswered = 0;
    bool limitsKnown = false;                // the limits were read (or cached)
    bool defaultKnown = false;
    std::vector<ScanDefinition> definitions; // by definition index
};

// A group while its parameters are being discovered.
struct ScanGroup {
    GroupDescription description;   // parameters stay empty until describe()
    int nextNumber = 0;             // the next parameter number whose name is to be asked
    int namesPending = 0;           // name reads queued or in flight
    bool walked = false;            // its numbers were asked in order for the drive's count
    // Numbers whose name read got no answer: whether a parameter lives there is unknown.
    QList<quint8> unsettled;
    QStringList unsettledReasons;
    std::map<quint8, ScanParameter> parameters; // by number

    // How many more names may still be asked: the drive's count not yet found or asked for,
    // bounded by the numbers left up to the highest one.
    int namesToAsk() const;
};

// Everything a scan has read so far; describe() turns it into what the scan hands out.
struct ScanState {
    std::map<quint8, ScanGroup> groups; // by group page
    // By COMBIVIS plaintext index and definition count.
    std::map<std::pair<quint16, int>, ScanPlaintextTable> plaintextTables;
    QString identification;
    QStringList problems; // reads whose failure leaves it unknown whether something exists

    ScanParameter &parameter(quint8 page, quint8 number);
    // A value or default outside its parameter's limits cannot be what the drive holds: it is
    // dropped and named as an error of the parameter (ReplyCheck's implausibleValue()).
    void rejectImplausibleValues();
    // Groups in the drive's display order, parameters by number, failed reads left out (their
    // reasons are in ParameterDescription::error).
    DriveDescription describe(Language language, const QString &stopReason) const;
};

// A drive text (Latin-1, at most 24 characters) up to its first NUL.
QString driveText(const QByteArray &bytes);

} // namespace DriveDesk
