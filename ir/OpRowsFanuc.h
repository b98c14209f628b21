// The FANUC 0i-D PMC rows: timers, counters, compares, transfer, search, conversion, flow,
// arithmetic and rotation control (fanuc-pmc.md 4.2, 6.3-6.10).
// Rows in Op order; one of the row files OpTable.cpp assembles (ir/OpTable.h is the interface).
#pragma once

#include "ir/OpRows.h"

namespace lj::oprows {

inline constexpr InstrInfo kFanucRows[] = {
    // ---- fanuc-a: FANUC PMC timers, counters, compares (fanuc-pmc.md 6.3, 6.4, 6.6) ----
    ROW(PmcTimer, PmcTc, Block, Required, 1, Result, Words, 3, konst("timer number", 1, 250),
        reg("preset", areas(Area::TimerData), false),
        reg("precision", areas(Area::TimerData), false), none(),
        "on-delay timer: preset count x the precision's unit"),
    ROW(PmcTimerAddr, PmcTc, Block, Required, 1, Result, Words, 3, konst("precision", 0, 7),
        reg("preset", kSrcAreas, false), reg("timer register", kDstAreas, true), none(),
        "on-delay timer with the preset and elapsed ms at any address"),
    ROW(PmcCounter, PmcTc, Block, Required, 4, Result, Edge, 3,
        regOrConst("preset", kSrcAreas, false), reg("current value", kDstAreas, true),
        konst("data type", 0, 1), none(),
        "preset/ring counter, up or down, counting rising edges of ACT; data type 0 binary, 1 "
        "the counter data type system parameter (BCD or binary)"),
    ROW(PmcCompareFlags, PmcTc, Block, Required, 1, None, None, 3, src("input data"),
        reg("comparison data", kSrcAreas, false), reg("flags", kDstAreas, true), none(),
        "flags.Z := input == comparison, flags.N := input < comparison"),
    ROW(BcdCompare, PmcTc, Block, Required, 2, Compare, None, 3, konst("relation", 0, 1),
        src("input data"), reg("comparison data", kSrcAreas, false), none(),
        "out := ACT and input <= / == comparison, BCD of 2 (BYT 0) or 4 digits (BYT 1)"),
    ROW(CompareNe, PmcTc, Block, Optional, 1, Compare, None, 2, src("data 1"), src("data 2"),
        none(), none(), "out := EN and a != b"),
    ROW(CompareBetween, PmcTc, Block, Optional, 1, Compare, None, 3, src("data 1"), src("data 2"),
        src("input"), none(), "out := EN and x between a and b (either order)"),
    // ---- fanuc-b: FANUC PMC transfer, search, conversion and flow (fanuc-pmc.md 4.2, 6.5, 6.7,
    // 6.8, 6.9; docs/fanuc-pmc.md). Control inputs are ST entries (ACT = ST0), W1 the Result;
    // the Edge slot holds W1 between executions of the instructions with a reset input. ----
    ROW(ParityCheck, Data, Block, Required, 3, Result, Edge, 1, reg("check data", kSrcAreas, false),
        none(), none(), none(), "W1 := parity error of the byte (odd/even select, reset, enable)"),
    ROW(ShiftWord, Data, Block, Required, 4, Result, Edge, 1, reg("shift data", kDstAreas, true),
        none(), none(), none(),
        "shift 16 bits by one (direction, continue, reset, enable); W1 := a 1 was shifted out"),
    ROW(BcdDecode, Data, Block, Required, 1, Result, None, 3, reg("decode data", kSrcAreas, false),
        konst("pattern", 0, 0x99), konst("digit mask", 0, 0xFF), none(),
        "W1 := ACT and (byte & mask) == pattern"),
    ROW(GroupDecode, Data, Block, Required, 1, None, None, 4, reg("decode data", kSrcAreas, false),
        i32Const("first value"), konst("groups", 1, 99), reg("output", kDstAreas, true),
        "output byte j bit k := ACT and data == first + 8 j + k"),
    ROW(BcdConvert, Data, Block, Required, 4, Result, Edge, 2,
        spanning(reg("input", kSrcAreas, false), 2), spanning(reg("output", kDstAreas, true), 2),
        none(), none(),
        "binary <-> BCD over 1 or 2 bytes (width, direction, reset, enable); W1 := error"),
    ROW(BcdConvertExt, Data, Block, Required, 4, Result, Edge, 3, reg("input", kSrcAreas, false),
        reg("output", kDstAreas, true), reg("flags", kDstAreas, true), none(),
        "binary <-> BCD over 1/2/4 bytes (sign, direction, reset, enable); R9000 N/V; W1 := error"),
    ROW(CodeTable, Data, Block, Required, 3, Result, Edge, 3, konst("table size", 0, 99),
        reg("index", kSrcAreas, false), spanning(reg("output", kDstAreas, true), 2), none(),
        "output := BCD table[BCD index] (width, reset, enable); W1 := bad index"),
    ROW(CodeTableBinary, Data, Block, Required, 2, Result, Edge, 3, konst("table size", 0, 256),
        reg("index", kSrcAreas, false), reg("output", kDstAreas, true), none(),
        "output := table[index] (reset, enable); W1 := bad index"),
    ROWX(TableRows, Data, Block, Required, 1, Enable, None, 9,
         "constant rows of the code-table block before them", i32Const("entry"), i32Const("entry"),
         i32Const("entry"), i32Const("entry"), i32Const("entry"), i32Const("entry"),
         i32Const("entry"), i32Const("entry"), i32Const("entry")),
    ROWX(
        IndexedTable, Data, Block, Required, 3, Result, Edge, 5,
        "nn items table[index] <-> data (read/write, reset, enable); W1 := index past the capacity",
        konst("items", 1, 99), reg("capacity", kSrcAreas, false),
        reg("table head", kDstAreas, true), reg("data", kDstAreas, true),
        reg("index", kSrcAreas, false)),
    ROW(SearchTable, Data, Block, Required, 2, Result, Edge, 4, reg("capacity", kSrcAreas, false),
        reg("table head", kSrcAreas, false), reg("search data", kSrcAreas, false),
        reg("result", kDstAreas, true), "result := index of the first equal item; W1 := not found"),
    ROW(CommonBegin, Data, Block, Required, 1, None, Edge, 0, none(), none(), none(), none(),
        "remember ACT for the coils up to COME"),
    ROW(CommonCoil, Data, Coil, None, 0, None, None, 3, bitWrite("coil"),
        konst("statements back to COM", 1, kI32Max), konst("kind", 0, 3), none(),
        "coil, negated coil, set or reset with input ST0 and the common line's enable (the two "
        "coils write 0 when it is off)"),
    // ---- fanuc-c: FANUC PMC arithmetic (fanuc-pmc.md 6.10 [EXT]; docs/fanuc-pmc.md
    // "Arithmetic"; the operation codes and flag bits are ir/PmcArith.h's). Inputs are ST
    // entries (ACT = ST0, RST = ST1, BYT = ST2); the Edge slot holds W1 between executions. ----
    ROWX(BinaryArith, PmcTc, Block, Required, 2, Result, Edge, 6,
         "result := operand 1 op operand 2 over 1/2/4 signed bytes (reset, enable); flags Z/N/V; "
         "the quotient's remainder; W1 := overflow or division by zero",
         konst("operation", 0, 3), reg("operand 1", kSrcAreas, false), src("operand 2"),
         reg("result", kDstAreas, true), reg("flags", kDstAreas, true),
         reg("remainder", kDstAreas, true)),
    ROW(BcdArith, PmcTc, Block, Required, 3, Result, Edge, 4, konst("operation", 0, 3),
        spanning(reg("operand 1", kSrcAreas, false), 2),
        spanning(regOrConst("operand 2", kSrcAreas, false), 2),
        spanning(reg("result", kDstAreas, true), 2),
        "result := operand 1 op operand 2 in BCD of 2 or 4 digits (width, reset, enable); "
        "W1 := a digit above 9, a result outside the digits or division by zero"),
    ROW(BcdConstant, PmcTc, Block, Required, 2, Result, None, 2, konst("BCD pattern", 0, 0x9999),
        spanning(reg("output", kDstAreas, true), 2), none(), none(),
        "output := the BCD pattern's low byte (width 0) or both bytes (width 1) when enabled; "
        "leaves the enable"),
    ROWX(BcdIndexedTable, Data, Block, Required, 4, Result, Edge, 4,
         "table[index] <-> data, 1 or 2 bytes, BCD index (width, read/write, reset, enable); W1 := "
         "bad index",
         konst("capacity", 1, 9999), reg("table head", kDstAreas, true),
         spanning(reg("data", kDstAreas, true), 2), spanning(reg("index", kSrcAreas, false), 2)),
    ROWX(BcdSearchTable, Data, Block, Required, 3, Result, Edge, 4,
         "result := BCD index of the first equal item, 1 or 2 bytes (width, reset, enable); W1 := "
         "not found",
         konst("capacity", 1, 9999), reg("table head", kSrcAreas, false),
         spanning(reg("search data", kSrcAreas, false), 2),
         spanning(reg("result", kDstAreas, true), 2)),
    // ---- FANUC PMC flow ----
    ROW(JumpOut, Core, Block, Required, 1, None, None, 1, label(), none(), none(), none(),
        "when ST0 = 1: leave this subroutine and every caller up to the sliced part, and go on "
        "there at the label"),
    // ---- rot: FANUC PMC rotation control (fanuc-pmc.md 6.10 [EXT]; docs/fanuc-pmc.md
    // "Rotation control"). Inputs are ST entries, ACT = ST0, INC, POS, DIR, [BYT,] RN0 above it;
    // the Edge slot holds W1 (the direction) between executions. ----
    ROW(BcdRotation, Data, Block, Required, 6, Result, Edge, 4, konst("rotor index count", 2, 9999),
        spanning(reg("current position", kSrcAreas, false), 2),
        spanning(reg("goal position", kSrcAreas, false), 2),
        spanning(reg("result", kDstAreas, true), 2),
        "result := the goal, the position before it or the steps to it, BCD of 2 or 4 digits "
        "(positions from 0 or 1, width, shortest way, position before, steps, enable); W1 := "
        "reverse"),
    ROWX(BinaryRotation, Data, Block, Required, 5, Result, Edge, 5,
         "result := the goal, the position before it or the steps to it, 1/2/4 signed bytes "
         "(positions from 0 or 1, shortest way, position before, steps, enable); W1 := reverse",
         onlyValues(konst("format (data length)", 1, 4), kDataLengths),
         reg("rotor index count", kSrcAreas, false), reg("current position", kSrcAreas, false),
         reg("goal position", kSrcAreas, false), reg("result", kDstAreas, true)),
};

} // namespace lj::oprows
