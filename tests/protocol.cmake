# tests of the shared service layer (Telegram, Acknowledge)
