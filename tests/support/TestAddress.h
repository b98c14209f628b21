// Addresses as tests write them (`X1.0`, `D5`, `T3.0`, `C3`) and reading/writing them in an
// lj_state, independently of the engines and of the io library (tests check engines with it).
#pragma once

#include "ir/Area.h"
#include "ladderjit/abi.h"

#include <cstdint>
#include <string_view>

namespace lj::test {

/// One test address: a bit (`bit` >= 0) or a whole element.
struct TestAddr {
  Area area = Area::None; ///< None: the text was not a valid address
  int32_t index = 0;      ///< element number (T/C: the timer/counter number)
  int8_t bit = -1;
};

/// Parse `X1.0`, `W7`, `T5.0`, `C3`... A bad address records a GoogleTest failure (it is a bug
/// in the test) and returns area None, which reads as 0 and ignores writes.
TestAddr parseTestAddr(std::string_view text);

/// Bit: 0/1. Element: at its width and signedness (DIALECT.md 1). `Tn` = elapsed_ms, `Cn` =
/// count, `Tn.0`/`Cn.0` = output bit.
int64_t readAddr(const lj_state &s, const TestAddr &a);

/// Bit: sets or clears only that bit. Element: keeps the low 8/16/32 bits. `Cn` sets the count.
void writeAddr(lj_state &s, const TestAddr &a, int64_t value);

} // namespace lj::test
