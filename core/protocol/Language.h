#pragma once

#include <QtGlobal>

namespace DriveDesk {

// The language id the services carry (names, plaintexts): 0 English, 1 German.
enum class Language : quint8 { English = 0, German = 1 };

} // namespace DriveDesk
