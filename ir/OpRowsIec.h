// The IEC IL rows: the Neza %TMi / %Ci function blocks (modicon-neza.md 3).
// Rows in Op order; one of the row files OpTable.cpp assembles (ir/OpTable.h is the interface).
#pragma once

#include "ir/OpRows.h"

namespace lj::oprows {

inline constexpr InstrInfo kIecRows[] = {
    // ---- iec3 (issue 16): the Neza %TMi / %Ci blocks (modicon-neza.md 3; semantics in
    // docs/iec-il.md "Function blocks"). Their state is in the block's words: a timer's five
    // (V, P, status, start low, start high), a counter's three (V, P, status) ----
    ROW(IecTimer, Core, Block, Required, 1, Enable, None, 3,
        spanning(reg("timer words", areas(Area::TimerData), true), 5),
        konst("timer type (0 TON, 1 TOF, 2 TP)", 0, 2),
        konst("time base (0 1 min, 1 1 s, 2 100 ms, 3 10 ms, 4 1 ms)", 0, 4), none(),
        "Neza timer %TMi: IN from ST0, which it leaves; Q and V in its words"),
    ROW(IecCounter, Core, Block, Required, 4, Result, None, 2,
        spanning(reg("counter words", areas(Area::CounterData), true), 3),
        konst("driven inputs (1 R, 2 S, 4 CU, 8 CD)", 1, 15), none(), none(),
        "Neza up/down counter %Ci: inputs R, S, CU, CD; out := D"),
};

} // namespace lj::oprows
