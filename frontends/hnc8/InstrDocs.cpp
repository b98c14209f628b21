// Per-mnemonic behaviour paragraphs and examples (from the reference files, sections cited) and
// the renderer of docs/instructions.md: operands, roles, kinds and areas come from the table.
#include "frontends/hnc8/InstrDocs.h"
#include "frontends/hnc8/Mnemonics.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <sstream>

namespace lj {

namespace {

constexpr InstrDoc kDocs[] = {
    {Op::Load, "Pushes the bit onto ST (DIALECT.md 3, hnc8-core.md 4.2).", "LD X1.0\nOUT Y2.0",
     "X1.0 = 1 gives Y2.0 = 1."},
    {Op::LoadNot, "Pushes the inverted bit.", "LDI X1.0\nOUT Y2.0", "X1.0 = 0 gives Y2.0 = 1."},
    {Op::LoadTrue, "Pushes 1 (the always-true contact); feeds blocks that should run every scan.",
     "LDT\nMOV 5 D0", "D0 = 5 every scan."},
    {Op::LoadRise,
     "Pushes the rising edge of the bit; each instance keeps its own edge memory, updated on every "
     "execution (DIALECT.md 3).",
     "LDP X1.0\nINC D0", "D0 counts the 0->1 changes of X1.0."},
    {Op::LoadFall, "Pushes the falling edge of the bit (own edge memory per instance).",
     "LDF X1.0\nINC D0", "D0 counts the 1->0 changes of X1.0."},
    {Op::And, "ST0 := ST0 and bit.", "LD X1.0\nAND X1.1\nOUT Y2.0", "Y2.0 = X1.0 and X1.1."},
    {Op::AndNot, "ST0 := ST0 and not bit.", "LD X1.0\nANI X1.1\nOUT Y2.0",
     "Y2.0 = X1.0 and not X1.1."},
    {Op::Or, "ST0 := ST0 or bit.", "LD X1.0\nOR X1.1\nOUT Y2.0", "Y2.0 = X1.0 or X1.1."},
    {Op::OrNot, "ST0 := ST0 or not bit.", "LD X1.0\nORI X1.1\nOUT Y2.0",
     "Y2.0 = X1.0 or not X1.1."},
    {Op::AndRise, "ST0 := ST0 and the rising edge of the bit.", "LD X1.0\nANDP X1.1\nINC D0",
     "D0 + 1 when X1.1 rises while X1.0 = 1."},
    {Op::AndFall, "ST0 := ST0 and the falling edge of the bit.", "LD X1.0\nANDF X1.1\nINC D0",
     "D0 + 1 when X1.1 falls while X1.0 = 1."},
    {Op::OrRise, "ST0 := ST0 or the rising edge of the bit.", "LD X1.0\nORP X1.1\nOUT Y2.0",
     "Y2.0 = X1.0, or 1 for the scan X1.1 rises."},
    {Op::OrFall, "ST0 := ST0 or the falling edge of the bit.", "LD X1.0\nORF X1.1\nOUT Y2.0",
     "Y2.0 = X1.0, or 1 for the scan X1.1 falls."},
    {Op::AndBlock, "Pops ST0 and ANDs it into the new ST0 (block AND); needs two entries.",
     "LD X1.0\nOR X1.1\nLD X1.2\nOR X1.3\nANB\nOUT Y2.0",
     "Y2.0 = (X1.0 or X1.1) and (X1.2 or X1.3)."},
    {Op::OrBlock, "Pops ST0 and ORs it into the new ST0 (block OR); needs two entries.",
     "LD X1.0\nAND X1.1\nLD X1.2\nAND X1.3\nORB\nOUT Y2.0",
     "Y2.0 = (X1.0 and X1.1) or (X1.2 and X1.3)."},
    {Op::BranchPush,
     "Pushes a copy of ST0 onto MS; ST unchanged. Every MPS must be closed by MPP in its scope.",
     "LD X1.0\nMPS\nAND X1.1\nOUT Y2.0\nMPP\nAND X1.2\nOUT Y2.1",
     "Y2.0 = X1.0 and X1.1; Y2.1 = X1.0 and X1.2."},
    {Op::BranchRead, "ST0 := top of MS (MS unchanged).",
     "LD X1.0\nMPS\nAND X1.1\nOUT Y2.0\nMRD\nAND X1.2\nOUT Y2.1\nMPP\nOUT Y2.2",
     "Three outputs share the branch point X1.0."},
    {Op::BranchPop, "ST0 := pop of MS.", "LD X1.0\nMPS\nAND X1.1\nOUT Y2.0\nMPP\nOUT Y2.1",
     "Y2.1 = X1.0."},
    {Op::Coil, "bit := ST0; ST unchanged. `WRT` is an alias (DIALECT.md 2).",
     "LD X1.0\nOUT Y2.0\nWRT R0.1", "Y2.0 = R0.1 = X1.0."},
    {Op::CoilNot, "bit := not ST0.", "LD X1.0\nOOUT Y2.0", "Y2.0 = not X1.0."},
    {Op::Set, "bit := bit or ST0 (latching set).", "LD X1.0\nSET Y2.0",
     "Y2.0 stays 1 once X1.0 was 1."},
    {Op::Reset, "bit := bit and not ST0 (reset).", "LD X1.1\nRST Y2.0", "X1.1 = 1 clears Y2.0."},
    {Op::EndInit, "Ends the init part, run once at start and at every (re)load (DIALECT.md 2).",
     "LDT\nMOV 100 D0\nIEND", "D0 = 100 after init."},
    {Op::EndCyclic, "Ends PLC1, run completely every tick. `END1` is an alias.",
     "LD X1.0\nOUT Y2.0\n1END", "Y2.0 follows X1.0 every tick."},
    {Op::EndSliced,
     "Ends PLC2, run in slices of `plc2_nvalue` statements (DIALECT.md 4). `END2` is an alias.",
     "1END\nLD X1.0\nOUT Y2.0\n2END", "Y2.0 follows X1.0 in the PLC2 slice."},
    {Op::Jump,
     "Jumps to the label of the same scope when ST0 = 1; a backward jump counts one watchdog step.",
     "LD X1.0\nJMP L1\nLDT\nINC D0\nLBL L1", "D0 counts only while X1.0 = 0."},
    {Op::Label, "Jump target; empties both stacks.", "LD X1.0\nJMP L7\nLDT\nOUT Y2.0\nLBL L7",
     "Y2.0 is written only while X1.0 = 0."},
    {Op::Call,
     "Calls the subroutine when ST0 = 1 (or with an empty ST); the callee has its own stacks.",
     "LD X1.0\nCALL S1\n1END\n2END\nSP S1\nLDT\nINC D0\nSPE", "D0 + 1 per scan while X1.0 = 1."},
    {Op::SubBegin, "Starts subroutine Sn (after the main parts).",
     "LDT\nCALL S2\n1END\n2END\nSP S2\nLDT\nOUT Y2.0\nSPE", "Y2.0 = 1."},
    {Op::SubEnd, "Ends a subroutine (returns).",
     "LDT\nCALL S3\n1END\n2END\nSP S3\nLDT\nMOV 7 D1\nSPE", "D1 = 7."},
    {Op::Return, "Returns from the subroutine when ST0 = 1 (or with an empty ST).",
     "LDT\nCALL S4\n1END\n2END\nSP S4\nLD X1.0\nRETN\nLDT\nINC D0\nSPE",
     "D0 counts only while X1.0 = 0."},
    {Op::LoopBegin,
     "Runs the body up to NEXT `count` times (count <= 0: skipped); each iteration is one watchdog "
     "step.",
     "LOOP 3\nLDT\nINC D0\nNEXT", "D0 + 3 per scan."},
    {Op::LoopEnd, "Ends a loop body.", "LOOP 2\nLDT\nINC D1\nNEXT", "D1 + 2 per scan."},
    {Op::Add, "dst := a + b (int32 wrap, truncated to the destination width); output = EN.",
     "LD X1.0\nADD D0 5 D1", "D1 = D0 + 5 while X1.0 = 1."},
    {Op::Subtract, "dst := a - b; output = EN.", "LDT\nSUB D0 D1 D2", "D2 = D0 - D1."},
    {Op::Multiply, "dst := a * b (low 32 bits); output = EN.", "LDT\nMUL D0 10 D2",
     "D2 = 10 * D0."},
    {Op::Divide,
     "dst := a / b truncated toward zero; b = 0 writes nothing, gives output 0 and counts "
     "fault_divzero; INT32_MIN / -1 = INT32_MIN.",
     "LDT\nDIV D0 4 D2", "D0 = 10 gives D2 = 2."},
    {Op::Increment, "x := x + 1 while EN = 1 (level triggered).", "LDP X1.0\nINC D0",
     "D0 + 1 per rising edge of X1.0."},
    {Op::Decrement, "x := x - 1 while EN = 1.", "LDP X1.0\nDEC D0",
     "D0 - 1 per rising edge of X1.0."},
    {Op::BitAnd, "dst := a & b.", "LDT\nWAND W0 255 W1", "W1 = low byte of W0."},
    {Op::BitOr, "dst := a | b.", "LDT\nWOR W0 1 W1", "W1 = W0 with bit 0 set."},
    {Op::BitXor, "dst := a ^ b.", "LDT\nWXOR W0 -1 W1", "W1 = not W0."},
    {Op::Negate, "x := -x (two's complement).", "LDP X1.0\nNEG D0", "D0 = 5 becomes -5."},
    {Op::CompareLe, "Output := EN and a <= b.", "LDT\nCMP D0 100\nOUT Y2.0", "Y2.0 = (D0 <= 100)."},
    {Op::CompareLt, "Output := EN and a < b.", "LDT\nLT D0 100\nOUT Y2.0", "Y2.0 = (D0 < 100)."},
    {Op::CompareRange, "Output := EN and lo < x < hi.", "LDT\nACMP 10 20 D0\nOUT Y2.0",
     "Y2.0 = 1 for D0 = 11..19."},
    {Op::CompareEq, "Output := EN and a == b.", "LDT\nCOIN 3 D0\nOUT Y2.0", "Y2.0 = (D0 == 3)."},
    {Op::Move, "dst := src (width conversion by the read rule and truncation); output = EN.",
     "LD X1.0\nMOV X2 D0", "D0 = X2 (0..255)."},
    {Op::RegisterCounter,
     "Ring counter with the value in a register; four inputs (count, start-from-1, down, reset; "
     "the first loaded is the count input), counts rising edges, reset has priority "
     "(hnc8-functions-1.md 3.3).",
     "LD X1.0\nLD X1.1\nLD X1.2\nLD X1.3\nCTR D0 5\nOUT Y2.0",
     "D0 counts X1.0 edges 0..5 in a ring; Y2.0 = count reached."},
    {Op::RingCounter, "Ring counter Cn counting up from 0; two inputs (count, reset).",
     "LD X1.0\nLD X1.1\nCTRC 0 3\nOUT Y2.0", "C0 counts X1.0 edges; Y2.0 = 1 at 3."},
    {Op::UpDownCounter, "Up/down ring counter Cn; four inputs (count, start 0/1, down, reset).",
     "LD X1.0\nLDI X1.1\nLDI X1.2\nLD X1.3\nCTUD 1 4\nOUT Y2.0", "C1 counts up X1.0 edges to 4."},
    {Op::OnDelayTimer,
     "On-delay timer Tn: output 1 once the input was 1 for the preset (unit 0 ms, 1 s, 2 min, 3 h) "
     "(hnc8-functions-1.md 3.4).",
     "LD X1.0\nTMRB 0 0 500\nOUT Y2.0", "Y2.0 = 1 after X1.0 was on for 500 ms."},
    {Op::OffDelayTimer,
     "Off-delay timer Tn: output follows the input on, stays 1 for the preset after it drops.",
     "LD X1.0\nSTMR 1 1 2\nOUT Y2.0", "Y2.0 stays on 2 s after X1.0 drops."},
    {Op::RisePulse,
     "Output := EN and not previous EN (one-scan pulse on the rising edge of the power flow); "
     "state per block number.",
     "LD X1.0\nPLS 0\nINC D0", "D0 + 1 per rising edge of X1.0."},
    {Op::FallPulse, "Output := not EN and previous EN (falling edge of the power flow).",
     "LD X1.0\nPLF 0\nINC D0", "D0 + 1 per falling edge of X1.0."},
    {Op::Toggle, "Toggles the held output on each rising edge of EN.", "LD X1.0\nALT 0\nOUT Y2.0",
     "Y2.0 toggles on every press of X1.0."},
    {Op::IndexedMove,
     "Indirect move: each side is (format, address): 0 = the register itself, 1 = B[value of the "
     "register], 2 = P[value] (hnc8-functions-2.md 0.6). An index out of range writes nothing, "
     "gives output 0 and counts fault_index.",
     "LDT\nXMOV 1 D1 1 D2", "D1 = 3, D2 = 7, B3 = 1234 gives B7 = 1234."},
    {Op::BlockMove,
     "Copies count elements from the source start to the destination start with memmove semantics "
     "and width conversion per element; the ranges must fit in their areas.",
     "LDT\nBMOV D0 D2 2", "D0 = 11, D1 = 22 gives D2 = 11, D3 = 22."},
    {Op::Fill,
     "Fills start..end (same area, inclusive) with the value, read once before the writes.",
     "LDT\nFMOV D0 D2 D3", "D3 = 9 gives D0 = D1 = D2 = 9."},
    {Op::Exchange,
     "Exchanges the two (format, address) operands (formats as XMOV), each truncated to its own "
     "width.",
     "LDT\nXCH 1 D1 1 D2", "D1 = 3, D2 = 7, B3 = 10, B7 = 20 gives B3 = 20, B7 = 10."},
    {Op::ZoneReset,
     "Clears start..end inclusive: whole registers (word form) or bits ordered index * width + bit "
     "(bit form); both bounds in the same area and form.",
     "LDT\nZRST D0 D1", "D0 = 5, D1 = 6, D2 = 7 gives D0 = D1 = 0, D2 = 7."},
    {Op::TableEncode,
     "dst := 1 << i for the first table entry i equal to the value, 0 when none "
     "(hnc8-functions-2.md 2.7).",
     "LD X1.0\nENCO D10 5 D1 D2", "D10..D14 = 3,5,7,8,9 and D1 = 7 give D2 = 4."},
    {Op::TableDecode, "dst := table entry of the lowest set bit of the value, 0 when none.",
     "LD X1.0\nDECO D10 5 D1 D2", "D10..D14 = 3,5,7,8,9 and D1 = 4 give D2 = 7."},
    {Op::TableLookup, "dst := table[index] for 0 <= index < n, otherwise unchanged.",
     "LD X1.0\nCOD D10 8 D1 D2", "D10..D17 = 50..120 and D1 = 2 give D2 = 70."},
    {Op::TableSearch,
     "Searches the table for the value: found -> index into the destination and output 1; not "
     "found -> destination unchanged, output 0.",
     "LD X1.0\nSER D0 4 D4 D5\nOUT Y2.0",
     "D0..D3 = 10,20,30,40 and D4 = 30 give D5 = 2, Y2.0 = 1."},
    {Op::Pack,
     "Packs count source elements into one register, the first in the least significant bits "
     "(element width of the source area).",
     "LD X1.0\nASSEM X0 4 D4", "X0..X3 = 0x11,0x22,0x33,0x44 give D4 = 0x44332211."},
    {Op::Unpack,
     "Splits one register into count destination elements (width of the destination area), lowest "
     "bits first.",
     "LD X1.0\nDISAS D0 4 Y0", "D0 = 0x44332211 gives Y0..Y3 = 0x11,0x22,0x33,0x44."},
    {Op::RangeConvert,
     "dst := (src - Pk) * (Pk+3 - Pk+2) / (Pk+1 - Pk) + Pk+2 in int64, truncated toward zero; Pk+1 "
     "= Pk writes nothing (hnc8-functions-2.md 2.13).",
     "LD X1.0\nACVT P0 D0 D1", "P0..P3 = 0,1000,0,100 and D0 = 500 give D1 = 50."},
    {Op::PointToNumber,
     "dst := the number of the first active point of four (point, number) pairs; no active point "
     "leaves dst unchanged.",
     "LDT\nPTN R0 Y30.0 0 Y30.1 1 Y30.2 2 Y30.3 3", "Only Y30.2 set gives R0 = 2."},
    {Op::NumberToPoint, "point i := (source == number i) for the four pairs.",
     "LDT\nNTP R0 0 Y30.0 1 Y30.1 2 Y30.2 3 Y30.3",
     "R0 = 1 gives Y30.1 = 1, Y30.0 = Y30.2 = Y30.3 = 0."},
    {Op::MCodeGet,
     "Output := EN and the channel requests the M code in one of its slots FC[48..55] "
     "(hnc8-functions-1.md 3.1).",
     "LD X2.0\nMGET 0 3\nWRT R4.0", "F2608 = 3 and X2.0 = 1 give R4.0 = 1."},
    {Op::MCodeAck,
     "Acknowledges the M code: each slot FC[48+k] holding it gets GC[48+k] := the code.",
     "LD X3.6\nMACK 0 3", "F2608 = 3 and X3.6 = 1 give G2608 = 3."},
    {Op::TCodeGet,
     "When a T code is pending (FC[56] != -1): writes it to the destination and outputs 1; a "
     "constant destination compares instead.",
     "LDT\nTGET 0 R5\nOUT R6.1", "F2616 = 12 gives R5 = 12, R6.1 = 1."},
    {Op::TCodeAck, "Acknowledges the channel's T code: GC[56] := FC[56].", "LD X3.4\nTACK 0",
     "F2616 = 12 and X3.4 = 1 give G2616 = 12."},
    {Op::HandwheelPulse,
     "Passes the pulse register to handwheel n through the host (`mpg_input`); no PLC memory is "
     "written.",
     "LD X3.4\nRTOMPG X40 0", "The host receives mpg_input(0, X40)."},
    {Op::TempSensor,
     "Sends the AD value of the X group (low byte Xn, high byte Xn+1), the board type and "
     "P[k..k+3] to the host (`temp_input`).",
     "TEMPSEN 0 X15 0 P30", "The host receives sensor 0's raw value."},
    {Op::PartCount,
     "Part count of the channel + 1 on every execution with EN = 1 (level triggered; drive it with "
     "a pulse).",
     "LDP X32.1\nPARTCNT 0", "G2579 + 1 per rising edge of X32.1."},
    {Op::PartClear, "Part count of the channel := 0.", "LD X32.2\nPARTCLR 0",
     "G2579 = 0 while X32.2 = 1."},
    {Op::HeadSensors,
     "When enable = 0: copies count temperatures from the host into D[start..] "
     "(hnc8-functions-2.md 2.21).",
     "LD X32.1\nHEADSEN 10 0 D1", "D1..D10 = the 10 temperatures."},
    {Op::VarGet,
     "Reads CNC variable (type, offset) through the host (`var_get`), floats scaled by 10^exp; a "
     "missing variable writes nothing.",
     "LD X32.1\nVARGET 1 1 0 R100", "#501 = 42.0 gives R100 = 42."},
    {Op::VarSet,
     "Writes the data source to CNC variable (type, offset) through the host (`var_set`), floats "
     "divided by 10^exp.",
     "LD X32.1\nVARSET 1 1 0 R100", "R100 = 42 sets #501 = 42.0."},
    {Op::ToolVectorOn, "Tool-vector direction of the channel on (host `tool_vector(ch, 1)`).",
     "LD X3.0\nTOOLSET 0", "Host call tool_vector(0, 1)."},
    {Op::ToolVectorOff, "Tool-vector direction of the channel off (host `tool_vector(ch, 0)`).",
     "LD X3.1\nTOOLCLR 0", "Host call tool_vector(0, 0)."},
    {Op::PanelDisplay,
     "Shows the value on the panel display: the host's encoding (`nixie_encode`), the raw value "
     "without a host; width 1 writes two bytes.",
     "LDT\nNIXIE R23 0 Y37", "Y37 = encoding of the tool number in R23."},
    {Op::ToolInUse, "Tells the host which tool the channel uses (`tool_in_use`).",
     "LDT\nTOOLUSE 0 R23", "Host call tool_in_use(0, R23)."},
    {Op::ToolLife,
     "Counts rising edges of EN (tool installs) per instance; when the count reaches the limit the "
     "response register is set for one scan and the count restarts (hnc8-cnc-interface.md 26).",
     "LD X4.0\nTOOLLIFE 0 10 R23", "R23 responds once every 10 installs."},
    {Op::ToolSelect,
     "Asks the host for the pocket of the commanded tool (`tool_select`): found -> pocket written, "
     "output 1; not found -> error code written, output 0.",
     "LD R154.1\nTOOL R40 R41 R42 R43\nOUT R181.1", "R43 = pocket of tool R41, R181.1 = 1."},
    {Op::SpindleAnalog,
     "Analog spindle: the host converts the commanded speed with the gear and the P block (5 "
     "words) into the DA value written to the reference register.",
     "LD X31.4\nSPDA 1 0 R1 R2 P5", "R2 = DA value of channel 1 spindle 0."},
    {Op::SlaveHomingEnable, "Slave-axis homing allowed (host `slave_home(axis, EN)`).",
     "LD X32.6\nSUBAXEN 0", "Host call slave_home(0, 1)."},
    {Op::HandwheelSet,
     "Handwheel n drives the axis with the override: reads the pulse delta from the host "
     "(`mpg_delta`) into the axis's handwheel words.",
     "LD X5.0\nMPGSET 0 2 100", "Axis 2 follows handwheel 0."},
    {Op::MagazineRotate,
     "Rotary magazine: five inputs (enable, numbering from 1, shortest path, count to the position "
     "before, result = steps); writes the target position or the step count; output 1 = reverse "
     "(hnc8-cnc-interface.md 59).",
     "LD R66.0\nLDT\nLDT\nLDI R66.0\nLDT\nROT 16 B0 R27 R59\nOUT Y2.0",
     "B0 = 2, R27 = 15 give R59 = 3 steps, Y2.0 = 1 (reverse)."},
    {Op::RaiseEvent, "Raises PLC event n on the rising edge of the input (host `event`).",
     "LD X30.4\nEVENT 122", "Host call event(122) once per press."},
    {Op::SaveRetained, "Asks the host to save the retentive data on the rising edge of the input.",
     "LD X30.4\nSAVEDATA", "Host call save_data() once per press."},
    {Op::ChannelModeSet,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[60].0-6 := the one-hot mode, GC[0].0-3 := its code.",
     "LD X36.0\nMDST 0 R0", "R0 = 4 requests manual mode in channel 0."},
    {Op::ChannelModeGet,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): destination := one-hot of the mode code FC[0].0-3.",
     "LDT\nMDGT 0 R1", "R1 = 4 while channel 0 reports manual mode."},
    {Op::MdiMode,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].0-3 := 8 (MDI).",
     "LD X36.4\nMDI 0", "Channel 0 requests MDI mode while X36.4 = 1."},
    {Op::MstLock,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[2].11 := ACT (M/S/T lock).",
     "LD X36.4\nMST 0", "G2562.11 = X36.4."},
    {Op::CycleStart,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].5 := ACT (cycle start).",
     "LD X36.4\nCYCLE 0", "G2560.5 = X36.4."},
    {Op::EmergencyStop,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].11 := ACT (emergency stop).",
     "LD X1.2\nSTOP 0", "G2560.11 = X1.2."},
    {Op::ChannelReset,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].13 := ACT (reset).",
     "LD X2.4\nRESET 0", "G2560.13 = X2.4."},
    {Op::ChannelSwitch,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): G2970 := channel while ACT (active channel).",
     "LD X36.4\nCHANSW 0", "G2970 = 0 while X36.4 = 1."},
    {Op::FeedHold,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].4 := ACT (feed hold).",
     "LD X36.4\nHOLD 0", "G2560.4 = X36.4."},
    {Op::CycleStartLamp,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FC[0].5 (cycle running).",
     "LDT\nCYCLED 0\nOUT Y36.4", "Y36.4 lights while channel 0 runs."},
    {Op::FeedHoldLamp,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FC[0].4 (feed hold active).",
     "LDT\nHOLDLED 0\nOUT Y36.5", "Y36.5 lights while channel 0 holds."},
    {Op::SkipG31,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[22] := the G31 number and GC[0].7 := 1 while ACT.",
     "LDP X31.4\nESCBLK 0 1", "G2582 = 1, G2560.7 = 1 for one scan per press."},
    {Op::RapidOverride,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[5] := override while ACT.",
     "LDT\nRPOVRD 0 R7", "G2565 = R7."},
    {Op::FeedOverride,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[4] := override while ACT.",
     "LDT\nFEEDOVRD 0 R7", "G2564 = R7."},
    {Op::SpindleOverride,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[6 + spindle] := override while ACT.",
     "LDT\nSPDLOVRD 0 0 R7", "G2566 = R7."},
    {Op::StepMultiplier,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): axis increment multiplier GA[8] := value while ACT.",
     "LDT\nSTEPMUL 0 R7", "G8 = R7."},
    {Op::DryRun,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].6 := ACT (dry run).",
     "LD Y32.2\nDRYRUN 2", "G2720.6 = Y32.2."},
    {Op::BlockSkip,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[1].2 := ACT (block skip).",
     "LD Y32.2\nSKIP 2", "G2721.2 = Y32.2."},
    {Op::UserInput,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): user input bit GC[24..25].bit := ACT.",
     "LD X5.1\nUSERIN 0 0 3", "G2584.3 = X5.1."},
    {Op::UserOutput,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): four bytes from the start := the 32 user outputs FC[44..45].",
     "LDT\nUSEROUT 0 0 Y40", "Y40..Y43 = F2604..F2605."},
    {Op::OptionalStop,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[1].3 := ACT (optional stop M01).",
     "LD X5.2\nSELSTOP 0", "G2561.3 = X5.2."},
    {Op::SpindleJog,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): spindle jog forward / reverse bits and jog words of the spindle axis.",
     "LD X31.4\nSPDLJOG 0 X32.4", "Spindle 0 turns forward while X31.4 and X32.4 are on."},
    {Op::BusSpindle,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): commanded S of FC[10+2sp] scaled by the override GC[6+sp] into "
     "GC[10+2sp], S acknowledged.",
     "LD X31.4\nSPDLBUS 0 1", "Channel 0 spindle 1 follows its S command."},
    {Op::BusSpindleGeared,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): as SPDLBUS, scaled by the gear's 5-word P block (P[k + 5(gear-1)..]).",
     "LD X31.4\nSPDLBUS1 0 1 R1 P2", "Channel 0 spindle 1 with gear R1 and parameters from P2."},
    {Op::SpindleOrient,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[2].12 := ACT (orient).",
     "LD X6.0\nSPDLORI 0", "G2.12 = X6.0."},
    {Op::SpindleOrientDone,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[3].8 (orientation done).",
     "LDT\nSPDLOROK 0\nOUT R10.1", "R10.1 = 1 once axis 0 is oriented."},
    {Op::SpindleZeroSpeed,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[2].15 (zero speed).",
     "LDT\nSPDLZERO 1\nOUT Y2.0", "Y2.0 = 1 while spindle axis 1 stands still."},
    {Op::SpindleSpeedReached,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[2].14 (speed reached).",
     "LDT\nSPDLRCH 1\nOUT Y2.0", "Y2.0 = 1 once spindle axis 1 is at speed."},
    {Op::SlaveRelease,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].11 := ACT (release the slave axis).",
     "LD X6.1\nDESYN 0", "G0.11 = X6.1."},
    {Op::AxisJog,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[4] := +1 / -1 by the direction bit (1 = +) while ACT, else 0.",
     "LD X6.2\nJOGSW 0 X6.3", "Axis 0 jogs + while X6.2 and X6.3 are on."},
    {Op::AxisStep,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[5] step by the direction bit (0 = +) while ACT.",
     "LD X6.2\nSTEPAXIS 0 X6.3", "Axis 0 steps while X6.2 is on."},
    {Op::JogSpeed,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): jog speed GA[6..7] := speed while ACT.",
     "LD X6.4\nJOGVEL 0 R8", "G6..G7 = R8."},
    {Op::HomingStart,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].4 := ACT (homing start).",
     "LD X7.0\nHOMRUN 0", "G0.4 = X7.0."},
    {Op::HomingStartDir,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].4 := ACT with the homing direction bit.",
     "LD X7.0\nHOMERUN1 0 X7.1", "Axis 0 homes in the direction of X7.1."},
    {Op::HomeDog,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].5 := ACT (home dog).",
     "LD X7.2\nHOMESW 0", "G0.5 = X7.2."},
    {Op::HomingDoneLamp,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[0].4 (homing done).",
     "LDT\nHOMLED 0\nOUT Y2.0", "Y2.0 = 1 once axis 0 is homed."},
    {Op::AxisEnable,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].7 := ACT (axis enable).",
     "LD X7.3\nAXEN 0", "G0.7 = X7.3."},
    {Op::AxisReady,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): pushes FA[2].8 (axis ready, bus) like a contact.",
     "AXRDY 0\nOUT Y2.0", "Y2.0 = axis 0 ready."},
    {Op::AxisLock,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].6 := ACT (axis lock).",
     "LD X7.4\nAXISLOCK 0", "G0.6 = X7.4."},
    {Op::AxisMoveRelative,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[52..55] := distance (0.001 units) and GA[1].1 := ACT (relative "
     "move).",
     "LDP X7.5\nAXISMOVE 4 D10", "Axis 4 moves by D10 / 1000."},
    {Op::AxisMoveAbsolute,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[48..51] := position and GA[1].0 := ACT (absolute move).",
     "LDP X7.6\nAXISMVTO 4 D11", "Axis 4 moves to D11 / 1000."},
    {Op::SecondSoftLimit,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[1].2 := ACT (second soft limit).",
     "LD X7.7\nAXLMF2 0", "G1.2 = X7.7."},
    {Op::PositiveLimitDog,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].0 := ACT (positive limit dog).",
     "LD X8.0\nAXISPLMT 0", "G0.0 = X8.0."},
    {Op::NegativeLimitDog,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[0].1 := ACT (negative limit dog).",
     "LD X8.1\nAXISNLMT 0", "G0.1 = X8.1."},
    {Op::ServoEnable,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[3].0 := ACT (servo enable).",
     "LD X8.2\nSVSW 0", "G3.0 = X8.2."},
    {Op::AxisControlMode,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GA[2].9-11 := the mode while ACT.",
     "LD X8.3\nAXISMODE 0 1", "Axis 0 in mode 1."},
    {Op::ReferencePoint,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[0].(8 + n - 1) (reference point n reached; n = 5 "
     "has no bit).",
     "LDT\nREFPT 0 2\nOUT Y2.0", "Y2.0 = 1 at reference point 2."},
    {Op::AxisHoming,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[0].2 (homing in progress).",
     "LDT\nAXISHOM2 0\nOUT Y2.0", "Y2.0 = 1 while axis 0 homes."},
    {Op::AxisMoving,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FA[0].0 (axis moving).",
     "LDT\nAXMOVING 0\nOUT Y2.0", "Y2.0 = 1 while axis 0 moves."},
    {Op::Alarm,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): alarm n: G3010 + (n-1)/16 bit (n-1)%16 := ACT; prompt n (501..884): "
     "G3056 + (n-501)/16.",
     "LD X3.4\nALARM 3", "G3010.2 = X3.4 (alarm 3)."},
    {Op::ResetRequested,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): output := ACT and FC[0].12 (reset requested, held until acknowledged).",
     "LDT\nRSTCHK 0\nOUT R5.0", "R5.0 = 1 while the NC waits for the PLC's reset."},
    {Op::ResetClear,
     "F/G words (hnc8-cnc-interface.md 4; the mapping lives in profiles/hnc8/CncTable.cpp, see "
     "docs/cnc-blocks.md): GC[0].9 := ACT (PLC reset done).",
     "LD X30.5\nRSTCLR 0", "G2560.9 = X30.5; the NC then clears FC[0].12."},
};

constexpr int kDocCount = static_cast<int>(sizeof(kDocs) / sizeof(kDocs[0]));

// One entry per operation HNC-8 spells (frontends/hnc8/Mnemonics.cpp), in the same order; the
// dialect-only rows of ir/OpTable.cpp have none (their dialect documents them).
constexpr bool docsInOrder() {
  for (int i = 1; i < kDocCount; ++i)
    if (static_cast<int>(kDocs[i - 1].op) >= static_cast<int>(kDocs[i].op)) return false;
  return true;
}
static_assert(docsInOrder(), "entries are in Op order");

/// `X Y F` for the register areas of a mask.
std::string areaList(AreaMask m) {
  std::string s;
  for (int a = 0; a < kAreaCount; ++a) {
    if (!hasArea(m, static_cast<Area>(a)) || hnc8::profile().area(static_cast<Area>(a)).count <= 0)
      continue;
    if (!s.empty()) s += ' ';
    s += hnc8::profile().area(static_cast<Area>(a)).name;
  }
  return s;
}

std::string constRange(const OperandSpec &sp) {
  if (sp.cmin == INT32_MIN && sp.cmax == INT32_MAX) return "any int32";
  return std::to_string(sp.cmin) + ".." + std::to_string(sp.cmax);
}

/// Kind column: constant range, register or bit address with the allowed areas.
std::string kindOf(const OperandSpec &sp) {
  if (hasArea(sp.areas, Area::Label)) return "label `L0`..`L9999`";
  if (hasArea(sp.areas, Area::Subroutine)) return "subroutine `S0`..`S511`";
  if (sp.isBit)
    return std::string(sp.wordOk ? "bit address or whole register" : "bit address") + " in " +
           areaList(sp.areas);
  if (sp.areas == 0) return "constant " + constRange(sp);
  if (sp.constOk) return "constant (" + constRange(sp) + ") or register in " + areaList(sp.areas);
  return "register in " + areaList(sp.areas);
}

const char *inputText(const InstrInfo &in) {
  switch (in.input) {
  case InputRule::Required:
    return "√ required: EN = ST0 (an empty ST gives 1 and a warning)";
  case InputRule::Optional:
    return "○ optional: EN = ST0, or 1 with an empty ST";
  default:
    return "× none";
  }
}

const char *outputText(const InstrInfo &in) {
  switch (in.output) {
  case OutputRule::Enable:
    return "√ ST0 := EN";
  case OutputRule::Compare:
    return "√ ST0 := EN and the condition";
  case OutputRule::Result:
    return "√ ST0 := the block's result";
  default:
    return "× ST0 unchanged";
  }
}

const char *stackText(StackRule r) {
  switch (r) {
  case StackRule::Push:
    return "pushes one entry";
  case StackRule::Combine:
    return "combines into ST0 (needs 1 entry)";
  case StackRule::BlockPop:
    return "pops one entry and combines it into ST0 (needs 2 entries)";
  case StackRule::MpsPush:
    return "pushes ST0 onto MS";
  case StackRule::MsRead:
    return "ST0 := top(MS)";
  case StackRule::MsPop:
    return "ST0 := pop(MS)";
  case StackRule::Coil:
    return "reads ST0, leaves ST unchanged (needs 1 entry)";
  case StackRule::Structural:
    return "empties ST and MS";
  default:
    return "function block";
  }
}

const char *stateText(StateKind k) {
  switch (k) {
  case StateKind::Edge:
    return "one edge bit per instance (`lj_state.edge`), zero at (re)load";
  case StateKind::Timer:
    return "timer Tn (`lj_state.T`)";
  case StateKind::Counter:
    return "counter Cn (`lj_state.C`)";
  case StateKind::Pls:
  case StateKind::Plf:
  case StateKind::Alt:
    return "one slot per block number (`pls_prev` / `plf_prev` / `alt_*`)";
  case StateKind::Words:
    return "two per-instance words (`lj_state.inst_word`)";
  default:
    return "none";
  }
}

const char *familyTitle(Family f) {
  switch (f) {
  case Family::Data:
    return "Data operations (hnc8-functions-2.md 2.2-2.13, 2.17-2.18)";
  case Family::Nc:
    return "NC services (hnc8-functions-1.md 3.1, hnc8-functions-2.md 2.19-2.23, "
           "hnc8-cnc-interface.md 2)";
  case Family::Cnc:
    return "CNC function blocks on F/G words (hnc8-cnc-interface.md 2)";
  default:
    return "Basic instructions, flow, math, compare, moves, counters, timers, edges";
  }
}

void renderEntry(std::ostream &o, const InstrInfo &in, const InstrDoc &d) {
  o << "\n## " << hnc8::mnemonicOf(in.op) << "\n\n" << in.summary << ".";
  if (const char *a = hnc8::mnemonicRow(in.op)->alias) o << " Alias: `" << a << "`.";
  o << "\n\n";
  if (in.operandCount == 0) {
    o << "Operands: none.\n\n";
  } else {
    o << "| # | role | kind and allowed areas | access |\n|---|---|---|---|\n";
    for (int i = 0; i < in.operandCount; ++i) {
      const OperandSpec &sp = in.operands[i];
      o << "| " << i + 1 << " | " << sp.role << " | " << kindOf(sp) << " | "
        << (sp.writes ? "written" : "read") << " |\n";
    }
    o << "\n";
  }
  o << "- Input (前置): " << inputText(in);
  if (in.inputs > 1) o << "; pops " << +in.inputs << " inputs (the first loaded is input 1)";
  o << "\n";
  if (in.stack == StackRule::Block)
    o << "- Output (后置): " << outputText(in) << "\n";
  else
    o << "- Stack: " << stackText(in.stack) << "\n";
  o << "- State: " << stateText(in.state) << "\n\n";
  o << d.behaviour << "\n\nExample:\n\n```\n" << d.example << "\n```\n\n" << d.effect << "\n";
}

} // namespace

const InstrDoc *instrDoc(Op op) {
  for (const InstrDoc &d : kDocs)
    if (d.op == op) return &d;
  return nullptr;
}

std::span<const InstrDoc> instrDocs() { return {kDocs, static_cast<size_t>(kDocCount)}; }

std::string renderInstructionReference() {
  std::ostringstream o;
  o << "<!-- Generated by tools/gen-instr-doc from ir/OpTable.cpp (the table), "
       "frontends/hnc8/Mnemonics.cpp and frontends/hnc8/InstrDocs.cpp; do not edit. -->\n"
    << "# Instruction reference\n\n"
    << "One entry per mnemonic of the HNC-8 manual (" << hnc8::mnemonicTable().size()
    << " instructions plus the aliases `WRT`, `END1`, `END2`), generated from the instruction "
       "table, so operands, areas and stack rules are exactly what the verifier checks. "
       "Semantics: DIALECT.md and docs/dialect-notes.md; CNC F/G mappings: "
       "docs/cnc-blocks.md.\n\n"
    << "Regenerate after changing the table or a text: `cmake --build build --target "
       "gen-instr-doc && build/tools/gen-instr-doc/gen-instr-doc -o docs/instructions.md`. "
       "The CTests `InstructionReference.*` (tests/catalogue) fail when this file is stale and "
       "checks that every "
       "example passes `ladderjit check`.\n\n"
    << "Operand kinds: a constant (decimal or `0x` hex, in the range shown), a register "
       "(`D5`, read by its area's width and sign: DIALECT.md 1) or a bit address (`X1.0`, "
       "`T3.0`). EN is the block's input; a block with EN = 0 does nothing unless its entry "
       "says otherwise (DIALECT.md 5).\n";
  Family last = Family::Core;
  bool first = true;
  for (const InstrInfo &in : instrTable()) {
    const InstrDoc *d = instrDoc(in.op);
    if (!hnc8::spells(in.op) || !d) continue; // another dialect's row (ir/OpTable.h)
    Family f = opFamily(in.op);
    if (first || f != last) o << "\n# " << familyTitle(f) << "\n";
    first = false;
    last = f;
    renderEntry(o, in, *d);
  }
  return o.str();
}

} // namespace lj
