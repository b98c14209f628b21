// Internal state of the simulated NC (hosts/SimNc.h) shared by its source files: per-channel,
// per-axis and system model, word offsets of the F/G map, and the helpers that touch words.
#pragma once

#include "hosts/SimNc.h"

#include <array>
#include <cstdint>
#include <deque>
#include <set>
#include <string>

namespace lj::hosts {

/// F/G word numbers (hnc8-cnc-interface.md 1.1-1.5).
namespace ncw {
constexpr int kAxisWords = 80;
constexpr int kChanBase = 2560;
constexpr int axis(int a, int k) { return a * kAxisWords + k; }
constexpr int chan(int c, int k) { return kChanBase + c * kAxisWords + k; }
constexpr int kAlarmBase = 3010;  ///< G3010-3025 PLC alarms 1..256
constexpr int kEventBase = 3040;  ///< G3040-3055 PLC events 0..255
constexpr int kPromptBase = 3056; ///< G3056-3071 PLC prompts 501..756
constexpr int kAreaWords = 16;
constexpr int kTempBase = 3080; ///< G3080-3099 temperature sensors 0..19
constexpr int kSensors = 20;
constexpr int kMpgs = 8; ///< handwheels 0..7
constexpr int kMSlots = 8;
} // namespace ncw

/// One channel (hnc8-cnc-interface.md 1.3/1.4, 3.2 "Channel model").
struct NcChannel {
  int mode = 0;                              ///< FC[0].0-3
  bool running = false;                      ///< FC[0].5 cycle start
  bool held = false;                         ///< FC[0].4 feed hold
  bool finished = false;                     ///< FC[1].2 program finished
  bool resetFlag = false;                    ///< FC[0].12, until GC[0].9
  bool estop = false;                        ///< GC[0].11 as last seen
  bool prevCycle = false;                    ///< GC[0].5 of the previous tick (rising edge)
  bool prevReset = false;                    ///< GC[0].13 of the previous tick
  std::array<int16_t, ncw::kMSlots> mslot{}; ///< FC[48..55], -1 = free
  std::array<bool, ncw::kMSlots> mcool{};    ///< freed by the last afterTick: shows -1 one tick
  std::array<bool, ncw::kMSlots> mgReset{};  ///< GC[48+k] := -1 at the next beforeTick
  std::deque<int16_t> mqueue;                ///< M codes waiting for a free slot
  int16_t tcode = -1;                        ///< FC[56]
  bool tcool = false, tgReset = false;
  std::deque<int16_t> tqueue;
  std::array<bool, 4> sflag{};   ///< FC[2].12-15
  std::array<int32_t, 4> sval{}; ///< FC[10..17], 0.001 rpm
  int16_t feedOvr = 0, rapidOvr = 0;
  std::array<int16_t, 4> spindleOvr{};
  int32_t partCount = 0; ///< G[2579+80c] as last read
  int32_t toolInUse = 0; ///< TOOLUSE
  bool toolVector = false;
  std::array<int32_t, 4> spindleCmd{}; ///< GC[10+2sp] (32 bit), the PLC's spindle command
  bool operator==(const NcChannel &) const = default;
};

/// Homing phases of one axis (3.2 "Homing state machine").
enum class HomePhase : uint8_t { Idle, Dog, ZSearch };

/// One axis or spindle (hnc8-cnc-interface.md 1.1/1.2, 3.2 "Axis model", "Spindle model").
struct NcAxis {
  int64_t pos = 0;      ///< machine position (FA[32..35] / GA[12..15]), 0.001 mm
  bool moving = false;  ///< FA[0].0
  int32_t lastStep = 0; ///< position change of the last tick (GA[20/21])
  int64_t enableSince = -1, servoSince = -1; ///< first tick GA[0].7 / GA[3].0 was on, -1 off
  bool ready = false, servoOk = false;       ///< FA[2].8 / FA[3].0
  bool locked = false, posLimit = false, negLimit = false, released = false; ///< mirrors
  uint16_t ctrlMode = 0; ///< GA[2].9-11 mirrored into FA[2].9-11
  HomePhase home = HomePhase::Idle;
  int64_t homeSince = 0; ///< tick the current phase started
  bool homed = false, homeFailed = false, zpulse = false;
  bool prevHomeStart = false;
  bool prevIncPlus = false, prevIncMinus = false; ///< panel keys in increment mode
  bool prevStep = false;                          ///< GA[5] of the previous tick
  bool prevPmcAbs = false, prevPmcRel = false;
  bool pmcActive = false;
  int64_t pmcTarget = 0;
  int32_t spindleSpeed = 0;  ///< actual speed (ramped)
  int32_t spindleTarget = 0; ///< commanded speed
  int64_t orientSince = -1;  ///< first tick GA[2].12 was on
  bool oriented = false;     ///< FA[3].8
  bool slaveHome = false;    ///< SUBAXEN
  bool operator==(const NcAxis &) const = default;
};

/// The whole model behind SimNc.
struct SimNc::Model {
  std::array<NcChannel, 4> ch{};
  std::array<NcAxis, 32> ax{};
  std::array<int32_t, 64> pocket{}; ///< tool in magazine pocket p (index p, 1-based use)
  std::array<bool, ncw::kSensors> tempSet{};
  std::array<int32_t, ncw::kSensors> temp{};
  std::array<int64_t, ncw::kMpgs> mpgPending{};
  std::array<int32_t, ncw::kMpgs> mpgRaw{};
  std::array<bool, ncw::kMpgs> mpgRawSeen{};
  std::array<uint16_t, 3 * ncw::kAreaWords> areaPrev{}; ///< alarms, events, prompts last seen
  int16_t activeChannel = 0;                            ///< G2970
  std::set<int> leftF, leftG; ///< words left to the host (stimulus / --set), never written
  bool operator==(const Model &) const = default;
};

/// Word helpers: unsigned bit access on int16 F/G words.
inline bool bitOf(int16_t w, int b) { return (static_cast<uint16_t>(w) >> b) & 1u; }
inline void setBit(int16_t &w, int b, bool on) {
  uint16_t u = static_cast<uint16_t>(w);
  u = on ? static_cast<uint16_t>(u | (1u << b)) : static_cast<uint16_t>(u & ~(1u << b));
  w = static_cast<int16_t>(u);
}
/// Little-endian multi-word values (low word at the lower address, hnc8-cnc-interface.md 0).
int64_t readWords(const int16_t *area, int word, int count);
void writeWords(int16_t *area, int word, int count, int64_t v);

// Axis and spindle model (SimNcAxes.cpp): consume G after a tick, publish F before a tick.
void axesAfterTick(SimNc::Model &m, const SimNcConfig &cfg, const lj_state &s, int64_t tick,
                   NcLog<NcEvent> &log);
void axesPublish(SimNc::Model &m, const SimNcConfig &cfg, lj_state &s);
/// Whether an axis of channel c is in homing phase 2 (FC[0].15: mode switch refused).
bool channelZSearch(const SimNc::Model &m, const SimNcConfig &cfg, int c);
/// Channel owning axis a, or -1.
int axisChannel(const SimNcConfig &cfg, int a);

} // namespace lj::hosts
