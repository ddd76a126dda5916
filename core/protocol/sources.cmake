target_sources(drivedesk_core PRIVATE
    protocol/Acknowledge.cpp protocol/Acknowledge.h
    protocol/Codec.cpp protocol/Codec.h
    protocol/Language.h
    protocol/Telegram.cpp protocol/Telegram.h
)
