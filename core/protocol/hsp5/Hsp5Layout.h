#pragma once

#include "protocol/Telegram.h"

#include <optional>

namespace DriveDesk {

// The length of one HSP5 telegram kind (service, access, direction), as the table in chapter 2
// of seed 000 gives it, and where its variable part is counted.
struct Hsp5Layout
{
    int length = 0;     // byte 0 through the BCC, without the text or data
    int countByte = -1; // 0-based offset of the text / data length byte; -1 = fixed length
    int maxCount = 0;   // 24 for texts, 64 for field-bus data

    bool isVariable() const { return countByte >= 0; }
    int lengthWith(int count) const { return length + (isVariable() ? count : 0); }
    bool operator==(const Hsp5Layout &) const = default;
};

constexpr int kHsp5MaxText = 24;

// Which services an HSP5 codec frames. A drive knows only the services of seed 000's table
// (0-12, 16-18, 32/33, 48-50): HSP5 has no framing characters, so a request of any other
// service cannot even be framed by it, and it loses step with the requests behind it.
// DriveDesk's layouts by analogy for services 13, 14, 19-21 and 51-53 are for a drive known
// to have them, and only on request.
enum class Hsp5Services : quint8 { Seed, WithExtensions };
constexpr int kHsp5MaxData = 64;

// The service a service number (byte 1, bits 0-5) names in HSP5, DriveDesk's extensions
// included where asked; nothing for numbers the chosen services do not define.
std::optional<Service> hsp5Service(int number, Hsp5Services services = Hsp5Services::Seed);

// The layout of one telegram kind, or nothing where HSP5 has no such telegram
// (Legacy, StatusInterrogation, Unspecified; service 21 write).
std::optional<Hsp5Layout> hsp5Layout(Service service, Access access, Direction direction,
                                     Hsp5Services services = Hsp5Services::Seed);

// Services 13, 14, 19-21 and 51-53: seed 000 does not define them, DriveDesk gives them HSP5
// layouts by analogy (docs/protocol-hsp5.md).
bool isHsp5Extension(Service service);

// Services 48-53 exchange process data both ways; their read/write bit ("X" in the seed's
// table) does not change the layout.
bool isHsp5Duplex(Service service);

} // namespace DriveDesk
