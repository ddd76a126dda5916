#pragma once

// The DIN66019(II) framing characters and addresses the simulated bus needs (seed 003).
namespace DriveDesk::DinFraming {

constexpr char kStx = 0x02;
constexpr char kEot = 0x04;
constexpr int kFirstGroupAddress = 240; // F0..FE: groups of 16 drives
constexpr int kBroadcastAddress = 255;

} // namespace DriveDesk::DinFraming
