// libFuzzer entry point for the plant-file reader (PlantFile::fromJson).
// Any input either loads or is refused with a reason and a line and column, never both and never
// neither. A file that loads saves to JSON that loads to the same plant and saves to the same
// bytes, and every link gives connection settings.
#include "plant/PlantFile.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace DriveDesk;

namespace {

[[noreturn]] void fail(const char *what, const QString &detail = {})
{
    std::fprintf(stderr, "fuzz_plantfile: %s\n", what);
    if (!detail.isEmpty())
        std::fprintf(stderr, "  %s\n", qPrintable(detail));
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    const std::optional<Plant> plant = PlantFile::fromJson(json, &error);
    if (!plant) {
        if (!error.contains(QLatin1String("(line ")))
            fail("refused without a place", error);
        return 0;
    }
    if (!error.isEmpty())
        fail("loaded, yet with an error", error);

    const QByteArray saved = PlantFile::toJson(*plant);
    const std::optional<Plant> again = PlantFile::fromJson(saved, &error);
    if (!again)
        fail("a loaded file, saved, does not load again", error);
    if (!(*again == *plant))
        fail("a loaded file, saved and loaded again, is a different plant");
    if (PlantFile::toJson(*again) != saved)
        fail("a loaded file saves differently the second time");
    for (const PlantLink &link : plant->links) {
        for (int address : link.addresses)
            (void)link.settings(address);
    }
    return 0;
}
