// JSON dump of an lj_state; the field list mirrors runtime_abi/include/ladderjit/abi.h.
#include "formats/StateJson.h"

#include <cstdint>
#include <cstring>
#include <iterator>

namespace lj::formats {

namespace {

template <typename T, size_t N> nlohmann::ordered_json array(const T (&a)[N]) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const T &v : a) out.push_back(static_cast<int64_t>(v));
  return out;
}

// Timer/counter number of slot k (inverse of lj_tc_slot).
int32_t tcNumber(int k) { return k < 128 ? k : k - 128 + 300; }

} // namespace

std::string dumpJson(const nlohmann::json &j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string dumpJson(const nlohmann::ordered_json &j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

bool isUtf8(std::string_view s) {
  size_t i = 0;
  while (i < s.size()) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    int n = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    if (n < 0 || s.size() - i <= static_cast<size_t>(n)) return false; // truncated
    uint32_t cp = n == 0 ? c : c & (0x3F >> n);
    for (int k = 1; k <= n; ++k) {
      unsigned char d = static_cast<unsigned char>(s[i + static_cast<size_t>(k)]);
      if ((d >> 6) != 0x2) return false;
      cp = cp << 6 | (d & 0x3F);
    }
    static constexpr uint32_t kMin[] = {0, 0x80, 0x800, 0x10000};
    if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    i += static_cast<size_t>(n) + 1;
  }
  return true;
}

nlohmann::ordered_json stateToJson(const lj_state &s) {
  nlohmann::ordered_json j;
  j["abi_version"] = LJ_ABI_VERSION;
  j["now_ms"] = s.now_ms;
  j["plc2_next_slice"] = s.plc2_next_slice;
  j["max_backward_steps"] = s.max_backward_steps;
  j["steps"] = s.steps;
  j["last_fault"] = s.last_fault;
  j["faults"] = {
      {"watchdog", s.fault_watchdog}, {"index", s.fault_index}, {"divzero", s.fault_divzero}};

  const lj_image &im = s.img;
  nlohmann::ordered_json areas;
  areas["X"] = array(im.X);
  areas["Y"] = array(im.Y);
  areas["F"] = array(im.F);
  areas["G"] = array(im.G);
  areas["R"] = array(im.R);
  areas["W"] = array(im.W);
  areas["D"] = array(im.D);
  areas["B"] = array(im.B);
  areas["P"] = array(im.P);
  j["areas"] = std::move(areas);

  nlohmann::ordered_json timers = nlohmann::ordered_json::array();
  for (int k = 0; k < LJ_TC_SLOTS; ++k) {
    const lj_timer &t = s.T[k];
    timers.push_back({{"n", tcNumber(k)},
                      {"elapsed_ms", t.elapsed_ms},
                      {"start_ms", t.start_ms},
                      {"out", t.out},
                      {"running", t.running}});
  }
  j["timers"] = std::move(timers);

  nlohmann::ordered_json counters = nlohmann::ordered_json::array();
  for (int k = 0; k < LJ_TC_SLOTS; ++k) {
    const lj_counter &c = s.C[k];
    counters.push_back({{"n", tcNumber(k)}, {"value", c.value}, {"out", c.out}, {"prev", c.prev}});
  }
  j["counters"] = std::move(counters);

  j["pls_prev"] = array(s.pls_prev);
  j["plf_prev"] = array(s.plf_prev);
  j["alt_prev"] = array(s.alt_prev);
  j["alt_state"] = array(s.alt_state);
  j["edge"] = array(s.edge);
  j["inst_word"] = array(s.inst_word);
  return j;
}

nlohmann::ordered_json stateToJson(const lj_state &s, const TargetProfile &tp) {
  nlohmann::ordered_json j = stateToJson(s);
  bool inMem = false;
  for (const AreaInfo &ai : tp.areas)
    inMem = inMem || (ai.count > 0 && ai.bytes > 0 && ai.offset >= offsetof(lj_state, mem));
  if (!inMem) return j;
  const auto *base = reinterpret_cast<const unsigned char *>(&s);
  nlohmann::ordered_json areas;
  for (int a = 0; a < kAreaCount; ++a) {
    const AreaInfo &ai = tp.areas[static_cast<size_t>(a)];
    if (ai.count <= 0 || ai.bytes == 0) continue;
    auto values = [&](int64_t lo, int64_t n) {
      nlohmann::ordered_json out = nlohmann::ordered_json::array();
      for (int64_t k = lo; k < lo + n; ++k) {
        const unsigned char *p = base + tp.elementOffset(static_cast<Area>(a), k);
        uint32_t raw = 0;
        std::memcpy(&raw, p, ai.bytes);
        int64_t v = raw;
        if (ai.isSigned)
          v = ai.bytes == 1   ? int64_t{static_cast<int8_t>(raw)}
              : ai.bytes == 2 ? int64_t{static_cast<int16_t>(raw)}
                              : int64_t{static_cast<int32_t>(raw)};
        out.push_back(v);
      }
      return out;
    };
    areas[ai.name] = values(0, ai.count);
    if (ai.upperCount > 0)
      areas[std::string(ai.name) + "@" + std::to_string(ai.upperLo)] =
          values(ai.upperLo, ai.upperCount);
  }
  j["areas"] = std::move(areas);
  int64_t nonzero = 0;
  for (uint8_t b : s.mem) nonzero += b != 0;
  j["mem_nonzero"] = nonzero;
  return j;
}

} // namespace lj::formats
