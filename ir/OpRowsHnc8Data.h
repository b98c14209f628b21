// The data operations of HNC-8 (hnc8-functions-2.md 2.2-2.13, 2.17-2.18; summary section 5).
// Rows in Op order; one of the row files OpTable.cpp assembles (ir/OpTable.h is the interface).
#pragma once

#include "ir/OpRows.h"

namespace lj::oprows {

inline constexpr InstrInfo kHnc8DataRows[] = {
    // ---- Data operations (hnc8-functions-2.md 2.2-2.13, 2.17-2.18; summary section 5) ----
    ROW(IndexedMove, Data, Block, Optional, 1, Enable, None, 4, konst("format 1", 0, 2),
        reg("address 1", kIndirectAreas, false), konst("format 2", 0, 2),
        reg("address 2", kIndirectAreas, true),
        "operand 2 := operand 1 (formats 0 reg, 1 B[], 2 P[])"),
    ROW(BlockMove, Data, Block, Optional, 1, Enable, None, 3, reg("source start", kSrcAreas, false),
        dst("destination start"), konst("count", 1, 1000), none(), "copy count elements (memmove)"),
    ROW(Fill, Data, Block, Optional, 1, None, None, 3, dst("destination start"),
        dst("destination end"), src("value"), none(), "fill start..end with the value"),
    ROW(Exchange, Data, Block, Optional, 1, None, None, 4, konst("format 1", 0, 2),
        reg("address 1", kIndirectAreas, true), konst("format 2", 0, 2),
        reg("address 2", kIndirectAreas, true), "exchange operand 1 and operand 2"),
    ROW(ZoneReset, Data, Block, Optional, 1, Enable, None, 2, zoneBound("start"), zoneBound("end"),
        none(), none(), "reset the registers or bits start..end"),
    ROW(TableEncode, Data, Block, Optional, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 32), src("value"), dst("destination"),
        "one-hot bit of the first table entry equal to the value"),
    ROW(TableDecode, Data, Block, Required, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 32), src("value"), dst("destination"),
        "table entry of the lowest set bit of the value"),
    ROW(TableLookup, Data, Block, Required, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 1000), src("index"), dst("destination"),
        "destination := table[index]"),
    ROW(TableSearch, Data, Block, Required, 1, Compare, None, 4,
        reg("table start", kSrcAreas, false), konst("table length", 1, 1000), src("value"),
        dst("index destination"),
        "index of the first table entry equal to the value; output = found"),
    ROW(Pack, Data, Block, Required, 1, None, None, 3, reg("source start", kSrcAreas, false),
        konst("count", 1, 32),
        reg("destination", areas(Area::NcControl, Area::Word, Area::DWord, Area::Retained), true),
        none(), "pack count registers into one"),
    ROW(Unpack, Data, Block, Required, 1, None, None, 3,
        reg("source",
            areas(Area::NcStatus, Area::NcControl, Area::Word, Area::DWord, Area::Param,
                  Area::Retained),
            false),
        konst("count", 1, 32),
        reg("destination start", areas(Area::Output, Area::NcControl, Area::Relay, Area::Word),
            true),
        none(), "split one register into count registers"),
    ROW(RangeConvert, Data, Block, Required, 1, None, None, 3, spanning(pblock(), 4), src("value"),
        dst("destination"), none(), "linear range conversion with the P parameter block"),
    ROWX(PointToNumber, Data, Block, Optional, 1, None, None, 9,
         "destination := number of the first active point", dst("destination"), bitRead("point 1"),
         i32Const("number 1"), bitRead("point 2"), i32Const("number 2"), bitRead("point 3"),
         i32Const("number 3"), bitRead("point 4"), i32Const("number 4")),
    ROWX(NumberToPoint, Data, Block, Optional, 1, None, None, 9, "point i := (source == number i)",
         reg("source", kSrcAreas, false), i32Const("number 1"), bitWrite("point 1"),
         i32Const("number 2"), bitWrite("point 2"), i32Const("number 3"), bitWrite("point 3"),
         i32Const("number 4"), bitWrite("point 4")),
};

} // namespace lj::oprows
