// The Modbus register map of `ladderjit serve --modbus` (docs/modbus-map.md): the built-in HNC-8
// map, or a map file naming addresses of the program's dialect (FANUC `D100:2`, IEC `%MW10`).
// Pure data, no sockets: the server (ModbusServer.h) and the unit tests use it alone.
#pragma once

#include "formats/Address.h"
#include "pipeline/Dialects.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lj::services {

/// The four Modbus data tables.
enum class MbTable { Coils, DiscreteInputs, HoldingRegisters, InputRegisters };

/// One block of consecutive Modbus addresses over consecutive elements (or bits) of one area.
struct MbBlock {
  enum class Kind : uint8_t { Bit, Byte, Word16, Word32 };
  enum class Access : uint8_t { ReadOnly, ReadWrite, InputWrite }; // InputWrite: writeInputs
  MbTable table = MbTable::Coils;
  uint32_t base = 0;     ///< first Modbus address
  uint32_t elements = 0; ///< elements (Bit: bits) it covers
  Kind kind = Kind::Bit;
  Access access = Access::ReadOnly;
  bool retained = false;     ///< a write waits for a durable retain save
  formats::CliAddress first; ///< the element (Bit: the bit) at `base`
  int32_t stride = 1;        ///< element numbers between consecutive elements (FANUC D100:2: 2)
  int32_t bitsPerElem = 8;   ///< Bit: bits of one element before the next element starts
  bool hnc8Slots = false;    ///< the built-in T/C blocks: element k is slot k (T0..T127, T300..)
  int line = 0;              ///< map file line (0: built in)
  std::string (*format)(const formats::CliAddress &) =
      nullptr; ///< the dialect's spelling (null: HNC-8)

  /// Registers (Bit: bits) one element takes.
  uint32_t width() const { return kind == Kind::Word32 ? 2 : 1; }
  /// Modbus addresses the block spans.
  uint32_t span() const { return elements * width(); }
  /// The address of element `k` (Bit: bit `k`).
  formats::CliAddress element(uint32_t k) const;
};

/// A whole map: the blocks of the four tables.
class ModbusMap {
public:
  /// The built-in map of HNC-8 programs (docs/modbus-map.md "Bits", "Registers").
  static const ModbusMap &hnc8();
  /// A map of these blocks (they must not overlap within one table).
  static ModbusMap fromBlocks(std::vector<MbBlock> blocks);
  /// Read a map file (docs/modbus-map.md "Map files") of `dialect`'s addresses; a START
  /// ADDRESS may be a name the program's `symbols` define (formats/Address.h parseAddressIn).
  /// Nothing with `error` = "FILE:LINE: problem" for the first bad line.
  static std::optional<ModbusMap> parse(std::string_view text, const std::string &file,
                                        const pipeline::Dialect &dialect, std::string &error,
                                        std::span<const Symbol> symbols = {});

  /// The block holding Modbus address `addr` of `table`, with the element's index in it and,
  /// for Word32, the register half (0 low, 1 high); nullptr when unmapped.
  const MbBlock *resolve(MbTable table, uint32_t addr, uint32_t &element, int &part) const;
  const std::vector<MbBlock> &blocks() const { return blocks_; }

private:
  std::vector<MbBlock> blocks_;
};

} // namespace lj::services
