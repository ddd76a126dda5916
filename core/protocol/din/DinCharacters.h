#pragma once

#include "protocol/Telegram.h"

#include <QByteArrayView>
#include <QString>

#include <optional>

namespace DriveDesk {

// The control characters of the DIN66019 line (seed 003, 2.2). Everything else a drive or
// master sends is a 7-bit character 20h..7Fh.
struct DinControl
{
    static constexpr char Stx = 0x02;
    static constexpr char Etx = 0x03;
    static constexpr char Eot = 0x04;
    static constexpr char Enq = 0x05;
    static constexpr char Ack = 0x06;
    static constexpr char Nak = 0x15;
};

// Block check character (seed 003, 2.3): XOR of the characters, plus 20h if below 20h so
// that it never looks like a control character.
quint8 dinBcc(QByteArrayView characters);

// A character that may stand inside a telegram: 20h..7Fh.
bool isDinLineCharacter(char c);
// A character a text field may hold: 20h..7Eh.
bool isDinTextCharacter(char c);
// '0'..'9', 'A'..'F'. Lower case is not a DIN hex digit: the seed sends upper case only.
bool isDinHexDigit(char c);
int dinHexValue(char c); // -1 for anything but an upper-case hex digit
char dinHexDigit(int value); // value 0..15

// Invoke id characters are '1'..'F'; returns 0 for anything else.
quint8 dinInvokeId(char c);
// The invoke id of `Svc IID ...` (after STX, if any), where it can still be read; else 0.
quint8 dinInvokeIdOf(QByteArrayView telegram);

// Service characters carry the service number + 47h ('G' = 0 ... 7Fh = 56).
bool isDinServiceCharacter(char c);
char dinServiceCharacter(Service service);
// The DIN66019II service the character stands for, if the protocol defines one.
std::optional<Service> dinServiceFromCharacter(char c);

// Which DIN66019II services can be read / written (Legacy and StatusInterrogation excluded).
bool isDinReadable(Service service);
bool isDinWritable(Service service);
// Services 48-53: one write request whose answer carries data and an error code.
bool isDinDuplex(Service service);

// A character named for an error message: 'G', ENQ or 7Fh.
QString dinCharacterName(char c);
// A byte in the seed's notation: 73h.
QString dinHexName(quint8 value);

} // namespace DriveDesk
