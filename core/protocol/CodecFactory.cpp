#include "Codec.h"

#include "din/DinCodec.h"
#include "hsp5/Hsp5Codec.h"

namespace DriveDesk {

std::unique_ptr<ProtocolCodec> makeCodec(Protocol protocol, CodecOptions options)
{
    if (protocol == Protocol::Hsp5)
        return std::make_unique<Hsp5Codec>(options.hsp5Extensions ? Hsp5Services::WithExtensions
                                                                  : Hsp5Services::Seed);
    return std::make_unique<DinCodec>(protocol);
}

} // namespace DriveDesk
