// libFuzzer entry point for the parameter-file reader (ParameterDocument::fromJson).
// Any input either loads or is refused with a reason, never both and never neither. A file that
// loads saves to JSON that loads to the same description and saves to the same bytes. Every
// value it holds is then shown and read back as the table would: a file's metadata (scaling,
// masks, limits) is as untrusted as its values, so the sanitizers judge that code as well.
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterFormat.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace DriveDesk;

namespace {

[[noreturn]] void fail(const char *what, const QString &detail = {})
{
    std::fprintf(stderr, "fuzz_parameterfile: %s\n", what);
    if (!detail.isEmpty())
        std::fprintf(stderr, "  %s\n", qPrintable(detail));
    std::abort();
}

void show(const ParameterFormat &format, qint32 raw)
{
    const QString text = format.text(raw);
    (void)format.limitsProblem(raw);
    QString error;
    if (!format.parse(text, &error, ParameterFormat::Limits::Ignore) && error.isEmpty())
        fail("a value shown is refused without a reason", text);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    const std::optional<DriveDescription> drive = ParameterDocument::fromJson(json, &error);
    if (!drive) {
        if (error.isEmpty())
            fail("refused without a reason");
        // A fault in the drive or the groups is named with its line and column.
        if ((error.startsWith(QLatin1String("groups")) || error.startsWith(QLatin1String("drive")))
            && !error.contains(QLatin1String(", column ")))
            fail("refused without naming the line and column", error);
        return 0;
    }
    if (!error.isEmpty())
        fail("loaded, yet with an error", error);

    const QByteArray saved = ParameterDocument::toJson(*drive);
    const std::optional<DriveDescription> again = ParameterDocument::fromJson(saved, &error);
    if (!again)
        fail("a loaded file, saved, does not load again", error);
    if (!(*again == *drive))
        fail("a loaded file, saved and loaded again, is a different description");
    if (ParameterDocument::toJson(*again) != saved)
        fail("a loaded file saves differently the second time");

    for (const GroupDescription &group : drive->groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (parameter.minimum > parameter.maximum)
                fail("loaded with min above max", parameter.name);
            const ParameterFormat format(parameter);
            show(format, parameter.minimum);
            show(format, parameter.maximum);
            show(format, parameter.defaultValue);
            for (const std::optional<qint32> &value : parameter.values) {
                if (value)
                    show(format, *value);
            }
        }
    }
    return 0;
}
