// The Modbus register map: the built-in HNC-8 blocks and map files of any dialect
// (docs/modbus-map.md "Map files").
#include "services/ModbusMap.h"

#include "profiles/Profiles.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace lj::services {
namespace {

using Kind = MbBlock::Kind;
using Access = MbBlock::Access;

std::string hnc8Text(const formats::CliAddress &a) {
  static const char letters[] = "XYFGRWDBPTC";
  std::string t(1, letters[static_cast<int>(a.area)]);
  t += std::to_string(a.index);
  if (a.bit >= 0) t += "." + std::to_string(a.bit);
  return t;
}

MbBlock builtIn(MbTable table, uint32_t base, Area area, uint32_t elements, Kind kind,
                Access access) {
  MbBlock b;
  b.table = table;
  b.base = base;
  b.elements = kind == Kind::Bit ? elements * 8 : elements;
  b.kind = kind;
  b.access = access;
  b.retained = area == Area::Retained;
  b.first.area = area;
  b.first.bit = kind == Kind::Bit ? 0 : -1;
  b.hnc8Slots = area == Area::Timer || area == Area::Counter;
  return b;
}

ModbusMap makeHnc8Map() {
  std::vector<MbBlock> v = {
      builtIn(MbTable::Coils, 0, Area::Output, LJ_Y_COUNT, Kind::Bit, Access::ReadWrite),
      builtIn(MbTable::Coils, 5000, Area::Relay, LJ_R_COUNT, Kind::Bit, Access::ReadWrite),
      builtIn(MbTable::Coils, 10000, Area::Input, LJ_X_COUNT, Kind::Bit, Access::InputWrite),
      builtIn(MbTable::DiscreteInputs, 0, Area::Input, LJ_X_COUNT, Kind::Bit, Access::ReadOnly),
      builtIn(MbTable::HoldingRegisters, 0, Area::Word, LJ_W_COUNT, Kind::Word16,
              Access::ReadWrite),
      builtIn(MbTable::HoldingRegisters, 1000, Area::DWord, LJ_D_COUNT, Kind::Word32,
              Access::ReadWrite),
      builtIn(MbTable::HoldingRegisters, 2000, Area::Retained, LJ_B_COUNT, Kind::Word32,
              Access::ReadWrite),
      builtIn(MbTable::HoldingRegisters, 3000, Area::NcControl, LJ_G_COUNT, Kind::Word16,
              Access::ReadWrite),
      builtIn(MbTable::HoldingRegisters, 7000, Area::Output, LJ_Y_COUNT, Kind::Byte,
              Access::ReadWrite),
      builtIn(MbTable::HoldingRegisters, 8000, Area::Relay, LJ_R_COUNT, Kind::Byte,
              Access::ReadWrite),
      builtIn(MbTable::HoldingRegisters, 9000, Area::Input, LJ_X_COUNT, Kind::Byte,
              Access::InputWrite),
      builtIn(MbTable::HoldingRegisters, 10000, Area::NcStatus, LJ_F_COUNT, Kind::Word16,
              Access::InputWrite),
      builtIn(MbTable::InputRegisters, 0, Area::NcStatus, LJ_F_COUNT, Kind::Word16,
              Access::ReadOnly),
      builtIn(MbTable::InputRegisters, 4000, Area::Input, LJ_X_COUNT, Kind::Byte, Access::ReadOnly),
      builtIn(MbTable::InputRegisters, 5000, Area::Param, LJ_P_COUNT, Kind::Word32,
              Access::ReadOnly),
      builtIn(MbTable::InputRegisters, 6000, Area::Timer, LJ_TC_SLOTS, Kind::Word32,
              Access::ReadOnly),
      builtIn(MbTable::InputRegisters, 7000, Area::Counter, LJ_TC_SLOTS, Kind::Word32,
              Access::ReadOnly),
  };
  return ModbusMap::fromBlocks(std::move(v));
}

const char *tableName(MbTable t) {
  switch (t) {
  case MbTable::Coils:
    return "coils";
  case MbTable::DiscreteInputs:
    return "discrete";
  case MbTable::HoldingRegisters:
    return "holding";
  case MbTable::InputRegisters:
    return "input";
  }
  return "?";
}

std::optional<MbTable> tableNamed(std::string_view w) {
  std::string l(w);
  for (char &c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (l == "coils" || l == "coil") return MbTable::Coils;
  if (l == "discrete" || l == "discrete-inputs") return MbTable::DiscreteInputs;
  if (l == "holding" || l == "holding-registers") return MbTable::HoldingRegisters;
  if (l == "input" || l == "input-registers") return MbTable::InputRegisters;
  return std::nullopt;
}

std::optional<uint32_t> number(std::string_view w, uint32_t lo, uint32_t hi) {
  if (w.empty() || w.size() > 6) return std::nullopt;
  uint32_t v = 0;
  for (char c : w) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<uint32_t>(c - '0');
  }
  if (v < lo || v > hi) return std::nullopt;
  return v;
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

const TargetProfile &profileOf(const formats::CliAddress &a) {
  return a.profile ? *a.profile : *profileNamed("hnc8");
}

} // namespace

formats::CliAddress MbBlock::element(uint32_t k) const {
  formats::CliAddress a = first;
  if (kind == Kind::Bit) {
    const uint32_t pos = static_cast<uint32_t>(first.bit) + k;
    a.index = first.index + static_cast<int32_t>(pos / static_cast<uint32_t>(bitsPerElem)) * stride;
    a.bit = static_cast<int8_t>(pos % static_cast<uint32_t>(bitsPerElem));
  } else if (hnc8Slots) {
    a.index = k < 128 ? static_cast<int32_t>(k) : static_cast<int32_t>(k) - 128 + 300;
  } else {
    a.index = first.index + static_cast<int32_t>(k) * stride;
  }
  a.text = format ? format(a) : hnc8Text(a);
  return a;
}

ModbusMap ModbusMap::fromBlocks(std::vector<MbBlock> blocks) {
  ModbusMap m;
  m.blocks_ = std::move(blocks);
  return m;
}

const ModbusMap &ModbusMap::hnc8() {
  static const ModbusMap m = makeHnc8Map();
  return m;
}

const MbBlock *ModbusMap::resolve(MbTable table, uint32_t addr, uint32_t &element,
                                  int &part) const {
  for (const MbBlock &b : blocks_) {
    if (b.table != table || addr < b.base || addr - b.base >= b.span()) continue;
    const uint32_t off = addr - b.base;
    element = off / b.width();
    part = static_cast<int>(off % b.width());
    return &b;
  }
  return nullptr;
}

std::optional<ModbusMap> ModbusMap::parse(std::string_view text, const std::string &file,
                                          const pipeline::Dialect &dialect, std::string &error,
                                          std::span<const Symbol> symbols) {
  ModbusMap m;
  int lineNo = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? text.npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++lineNo;
    if (size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::vector<std::string_view> w = words(line);
    if (w.empty()) continue;
    const std::string at = file + ":" + std::to_string(lineNo) + ": ";
    if (w.size() < 3 || w.size() > 4) {
      error = at + "expected TABLE START ADDRESS [COUNT], e.g. 'holding 100 D100:2 10'";
      return std::nullopt;
    }
    std::optional<MbTable> table = tableNamed(w[0]);
    if (!table) {
      error = at + "unknown table '" + std::string(w[0].substr(0, 40)) +
              "' (coils, discrete, holding, input)";
      return std::nullopt;
    }
    std::optional<uint32_t> base = number(w[1], 0, 65535);
    if (!base) {
      error = at + "start '" + std::string(w[1].substr(0, 40)) + "': expected 0..65535";
      return std::nullopt;
    }
    std::optional<uint32_t> count = w.size() == 4 ? number(w[3], 1, 65536) : 1u;
    if (!count) {
      error = at + "count '" + std::string(w[3].substr(0, 40)) + "': expected 1..65536";
      return std::nullopt;
    }
    std::string why;
    std::optional<formats::CliAddress> first =
        formats::parseAddressIn(dialect.parseAddress, symbols, w[2], why);
    if (!first) {
      error = at + why;
      return std::nullopt;
    }
    const TargetProfile &tp = profileOf(*first);
    const AreaInfo &info = tp.area(first->area);
    const bool bitTable = *table == MbTable::Coils || *table == MbTable::DiscreteInputs;
    MbBlock b;
    b.table = *table;
    b.base = *base;
    b.first = *first;
    b.line = lineNo;
    b.format = dialect.formatAddress;
    if (bitTable != first->isBit()) {
      error = at + std::string(tableName(*table)) + " take " +
              (bitTable ? "bit addresses (like X0.0 or %M3), not '"
                        : "element addresses (like D100:2 or %MW10), not '") +
              first->text + "'";
      return std::nullopt;
    }
    const int bytes = first->width ? first->width : info.bytes;
    if (bitTable) {
      b.kind = Kind::Bit;
      b.bitsPerElem = tp.bitWidth(first->area);
      b.elements = *count;
    } else {
      if (bytes != 1 && bytes != 2 && bytes != 4) {
        error =
            at + "'" + first->text + "' has no register value (timers: use T.. of the data areas)";
        return std::nullopt;
      }
      b.kind = bytes == 1 ? Kind::Byte : bytes == 2 ? Kind::Word16 : Kind::Word32;
      b.elements = *count;
      b.stride = first->width && info.bytes ? std::max(1, first->width / info.bytes) : 1;
    }
    if (b.base + b.span() > 65536) {
      error = at + std::to_string(*count) + " elements from address " + std::to_string(*base) +
              " run past Modbus address 65535";
      return std::nullopt;
    }
    const bool input = first->area == Area::Input || first->area == Area::NcStatus;
    if (*table == MbTable::DiscreteInputs || *table == MbTable::InputRegisters || !info.writable)
      b.access = input && (*table == MbTable::Coils || *table == MbTable::HoldingRegisters)
                     ? Access::InputWrite
                     : Access::ReadOnly;
    else
      b.access = Access::ReadWrite;
    b.retained = (tp.retentiveAreas & bit(first->area)) != 0;
    // Every element must exist, in the first address's area (FANUC X127 -> X200 is a gap).
    for (uint32_t k = 0; k < b.elements; ++k) {
      formats::CliAddress e = b.element(k);
      std::string shown = e.text, why2;
      std::optional<formats::CliAddress> back = dialect.parseAddress(shown, why2);
      if (!back || back->area != e.area || back->index != e.index || back->bit != e.bit) {
        error = at + std::to_string(*count) + " elements from '" + first->text +
                "' run out of its area: element " + std::to_string(k + 1) + " would be '" + shown +
                "'" + (why2.empty() ? "" : " (" + why2 + ")");
        return std::nullopt;
      }
    }
    for (const MbBlock &o : m.blocks_) {
      if (o.table == b.table && b.base < o.base + o.span() && o.base < b.base + b.span()) {
        error = at + std::string(tableName(b.table)) + " " + std::to_string(b.base) + ".." +
                std::to_string(b.base + b.span() - 1) + " overlap line " + std::to_string(o.line) +
                " (" + std::to_string(o.base) + ".." + std::to_string(o.base + o.span() - 1) + ")";
        return std::nullopt;
      }
    }
    m.blocks_.push_back(std::move(b));
  }
  if (m.blocks_.empty()) {
    error = file + ": the map file maps nothing (one line per block: TABLE START ADDRESS [COUNT])";
    return std::nullopt;
  }
  return m;
}

} // namespace lj::services
