// The ClassicLadder rows: the old timer %T, the monostable %M, the counter %C and the IEC timer
// %TM of LinuxCNC 2.9's classicladder_rt (`calc.c`), and the scan clock their time comes from
// (docs/classicladder.md "Timers, monostables and counters"). Family ClassicLadder: the
// interpreter's interp/InterpClassicLadder.cpp, the lowering's lowering/EmitClassicLadder.cpp.
// Their whole state is in the block area's 32-bit words (ir/ClBlocks.h).
// Rows in Op order; one of the row files OpTable.cpp assembles (ir/OpTable.h is the interface).
#pragma once

#include "ir/OpRows.h"

namespace lj::oprows {

inline constexpr InstrInfo kClassicLadderRows[] = {
    ROW(ClClock, ClassicLadder, Block, None, 0, None, None, 2,
        spanning(reg("clock words", areas(Area::TimerData), true), 2),
        konst("mode (0 scan, 1 power-up)", 0, 1), none(), none(),
        "the scan clock: dt := now_ms - the previous scan's now_ms (power-up: the first period)"),
    ROW(ClTimer, ClassicLadder, Block, Required, 2, Result, None, 2,
        spanning(reg("timer words", areas(Area::TimerData), true), 4),
        spanning(reg("clock words", areas(Area::TimerData), false), 2), none(), none(),
        "ClassicLadder old timer %Tn: inputs E, C; V counts down by dt while E and C; out := D"),
    ROW(ClMonostable, ClassicLadder, Block, Required, 1, Result, None, 2,
        spanning(reg("monostable words", areas(Area::TimerData), true), 4),
        spanning(reg("clock words", areas(Area::TimerData), false), 2), none(), none(),
        "ClassicLadder monostable %Mn: a rising input starts it when V is 0; out := R"),
    ROW(ClCounter, ClassicLadder, Block, Required, 4, Result, None, 1,
        spanning(reg("counter words", areas(Area::TimerData), true), 8), none(), none(), none(),
        "ClassicLadder counter %Cn: inputs R, P, U, D; D = (V == P); out := E"),
    ROW(ClIecTimer, ClassicLadder, Block, Required, 1, Result, None, 4,
        spanning(reg("IEC timer words", areas(Area::TimerData), true), 6),
        spanning(reg("clock words", areas(Area::TimerData), false), 2),
        konst("mode (0 TON, 1 TOF, 2 TP)", 0, 2), konst("time base in ms", 1, 60000),
        "ClassicLadder IEC timer %TMn: V counts base units, Q one scan after V reaches P"),
};

} // namespace lj::oprows
