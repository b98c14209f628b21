// A ClassicLadder project as its files describe it (docs/classicladder.md "The model"): general
// parameters, sections, rungs as grids of cells, timers, monostables, counters, IEC timers,
// arithmetic expressions (parsed), symbols and the sequential (Grafcet) pages. Typed, located,
// and free of any IR: the network front end maps it onto the IR (phase 2).
#pragma once

#include "frontends/classicladder/Expression.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lj::classicladder {

/// Which ClassicLadder wrote the project: LinuxCNC's 0.7/0.8 (`.clp`, 10x6 rungs, `#VER=2.0`)
/// or the author's 0.9 (`.clprj`, 12x8 rungs, `#VER=3.0`), which LinuxCNC does not load.
enum class Flavor : uint8_t { LinuxCnc, Upstream09 };

/// Grid size of a rung for a flavor (classicladder.h RUNG_WIDTH / RUNG_HEIGHT).
int rungWidth(Flavor f);
int rungHeight(Flavor f);

/// Element codes of a cell (classicladder.h ELE_*). 100..105 are editor tool codes that occur
/// in real files (type 103, the eraser) and act like FREE; 14 exists only in 0.9.
enum class Ele : int16_t {
  Free = 0,
  Contact = 1,    ///< -[ ]-
  ContactNot = 2, ///< -[/]-
  Rising = 3,     ///< rising-edge contact
  Falling = 4,    ///< falling-edge contact
  Connection = 9, ///< horizontal wire
  Timer = 10,     ///< old timer %T, 2x2
  Monostable = 11,
  Counter = 12,  ///< 2x4
  TimerIec = 13, ///< %TM, 2x2
  Register = 14, ///< 0.9 only
  Compare = 20,  ///< 3x1
  Coil = 50,
  CoilNot = 51,
  Set = 52,
  Reset = 53,
  Jump = 54,
  Call = 55,
  Operate = 60, ///< 3x1, output column
  Unusable = 99 ///< the dead cells of a block
};

/// True for the codes a reader accepts (100..105 included; 14 only for 0.9).
bool knownElement(int code, Flavor f);
/// The name used in messages and docs ("contact", "IEC timer", ...).
const char *elementName(int code);
/// Coils and the other elements of the output column (50..55, 60).
bool isOutputElement(int code);
/// Width and height of the block an element occupies (1x1 for contacts and coils).
void elementSize(int code, int &width, int &height);

/// Variable type codes (classicladder.h VAR_*), as stored in cells and `@type/num@`.
enum class Var : int16_t {
  Bit = 0,           ///< %B
  TimerDone = 10,    ///< %Tn.D
  TimerRunning = 11, ///< %Tn.R
  TimerIecDone = 15, ///< %TMn.Q
  MonoRunning = 20,  ///< %Mn.R
  CounterDone = 25,  ///< %Cn.D
  CounterEmpty = 26, ///< %Cn.E
  CounterFull = 27,  ///< %Cn.F
  Step = 30,         ///< %Xn (step number)
  Input = 50,        ///< %I  (HAL in-NN)
  Output = 60,       ///< %Q  (HAL out-NN)
  System = 70,       ///< %S
  Error = 75,        ///< %E
  Word = 200,        ///< %W
  StepTime = 220,    ///< %Xn.V (seconds)
  TimerPreset = 230, ///< %Tn.P
  TimerValue = 231,  ///< %Tn.V
  MonoPreset = 240,  ///< %Mn.P
  MonoValue = 241,   ///< %Mn.V
  CounterPreset = 250,
  CounterValue = 251,
  TimerIecPreset = 260,
  TimerIecValue = 261,
  InputWord = 270,  ///< %IW (HAL s32in-NN)
  OutputWord = 280, ///< %QW (HAL s32out-NN)
  SystemWord = 290, ///< %SW
  InputFloat = 300, ///< %IF (HAL floatin-NN, read as int); a register input in 0.9
  OutputFloat = 310 ///< %QF (HAL floatout-NN)
};

/// True for the codes of the flavor (0.9 adds 65 user LED, 80/81 register empty/full and
/// 300/301/302 register in/out/count, where 300 collides with LinuxCNC's %IF).
bool knownVar(int code, Flavor f);
/// Boolean variables (`TEST_VAR_IS_A_BOOL`: code < 199); words are read as non-zero = true.
inline bool isBoolVar(int code) { return code < 199; }
/// `%I3`, `%TM0.Q`, `%QW2`; `?type/num` for a code without a name.
std::string varName(int type, int num);
/// The inverse of varName for the LinuxCNC codes (symbols.csv's first column); nullopt if the
/// text is not a variable name.
std::optional<VarRef> parseVarName(const std::string &text);

/// One cell of a rung grid: `Type-ConnectedWithTop-VarType/VarNum[IdxType/IdxNum]`.
struct Cell {
  int16_t type = 0;              ///< an Ele code (or 100..105)
  bool connectedWithTop = false; ///< a vertical wire on the cell's left edge up to row y-1
  int32_t varType = 0;
  int32_t varNum = 0;     ///< operand; block number; jump target rung; sub-routine number
  int32_t indexType = -1; ///< master only: `[type/num]` index variable, -1 when absent
  int32_t indexNum = -1;
};

/// One `rung_<n>.csv`.
struct Rung {
  int32_t index = 0;     ///< the n of the file name: a slot of the engine's rung array
  std::string label;     ///< at most 9 characters kept
  std::string comment;   ///< at most 29 characters kept
  int32_t prevRung = -1; ///< cosmetic
  int32_t nextRung = -1; ///< the execution chain, -1 ends it
  int32_t version = 2;   ///< #VER (3 in 0.9)
  int32_t linesUsed = 0; ///< #NBRLINES (0.9), else the grid height
  std::vector<std::vector<Cell>> cells; ///< cells[x][y], x = column (0 touches the rail)
  std::vector<int32_t> rowLines;        ///< line of row y in the project file (0 when unknown)
  const Cell &at(int x, int y) const { return cells[x][y]; }
};

enum class Language : uint8_t { Ladder = 0, Sequential = 1 };

/// One line of `sections.csv`.
struct Section {
  int32_t number = 0;
  std::string name;
  Language language = Language::Ladder;
  int32_t subRoutine = -1; ///< -1 = main section, n >= 0 = SRn (run only by a CALL coil)
  int32_t firstRung = 0;
  int32_t lastRung = 0;
  int32_t sequentialPage = 0;
  /// The rungs of a ladder section in execution order (FirstRung .. NextRung .. LastRung).
  std::vector<int32_t> order;
};

/// Old timer `%T` and monostable `%M`: `base,preset` (ms = preset x base).
struct TimerParams {
  int32_t baseMs = 1000;
  int32_t preset = 0; ///< in base units
};

/// IEC timer `%TM`: `base,preset,mode`.
enum class IecMode : uint8_t { Ton = 0, Tof = 1, Tp = 2 };
struct TimerIecParams {
  int32_t baseMs = 1000;
  int32_t preset = 0; ///< in base units (kept so by the loader)
  IecMode mode = IecMode::Ton;
};

/// A line of `symbols.csv`: display only.
struct Symbol {
  std::string varName;       ///< as written: `%I0`
  std::optional<VarRef> var; ///< parsed when the name is a LinuxCNC variable
  std::string symbol;  ///< empty when longer than 9 characters (ClassicLadder leaves it empty)
  std::string comment; ///< empty when longer than 49 characters
};

/// Grafcet (`sequential.csv`): step slots, transitions, their conditions, comments.
struct Step {
  int32_t slot = 0; ///< 0..127
  bool initial = false;
  int32_t stepNumber = 0; ///< the n of %Xn
  int32_t page = 0;
  int32_t x = 0, y = 0;
};
struct Transition {
  int32_t slot = 0;                            ///< 0..255, the firing order
  std::vector<int32_t> activate;               ///< step slots, -1 entries dropped
  std::vector<int32_t> deactivate;             ///< step slots
  std::vector<int32_t> linkedStart, linkedEnd; ///< drawing only
  int32_t page = 0;
  int32_t x = 0, y = 0;
  VarRef condition{}; ///< from the `C` line; type -1 when none
};
struct SeqComment {
  int32_t slot = 0, page = 0, x = 0, y = 0;
  std::string text;
};
struct Sequential {
  std::vector<Step> steps;
  std::vector<Transition> transitions;
  std::vector<SeqComment> comments;
  bool empty() const { return steps.empty() && transitions.empty(); }
};

/// The sizes of `general.txt`, defaulting to classicladder_rt's loadrt defaults. LinuxCNC
/// ignores the file (sizes come from loadrt), so these are what a project says it needs.
struct Sizes {
  int32_t rungs = 100, bits = 20, words = 20, timers = 10, monostables = 10, counters = 10,
          timersIec = 10, physInputs = 15, physOutputs = 15, arithmExpr = 100, sections = 10,
          symbols = 0, s32in = 10, s32out = 10, floatIn = 10, floatOut = 10;
};

/// One arithmetic expression slot (`arithmetic_expressions.csv`).
struct ArithExpr {
  int32_t index = 0;
  Expression expr;  ///< parsed on read; how it is used (compare / operate) is known from cells
  int32_t line = 0; ///< line in the project file (0 for a folder file)
};

/// A whole project.
struct Project {
  std::string path;
  Flavor flavor = Flavor::LinuxCnc;
  std::map<std::string, std::string> general; ///< every KEY=value of general.txt
  Sizes sizes;
  /// The smallest sizes the rungs need (highest number used + 1 of each kind; 0 when unused),
  /// which may exceed `sizes`: demo_mazak uses %T10 with SIZE_NBR_TIMERS=10. A harness loads
  /// classicladder_rt with the larger of the two.
  Sizes needed{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  int32_t periodMs = 0; ///< PERIODIC_REFRESH (0 when absent); LinuxCNC uses the HAL thread's
  std::vector<Section> sections; ///< in file order; sections.csv absent = one V1 section
  bool hasSectionsFile = false;
  std::map<int32_t, Rung> rungs; ///< by rung index
  std::vector<TimerParams> timers;
  std::vector<TimerParams> monostables;
  std::vector<int32_t> counterPresets;
  std::vector<TimerIecParams> timersIec;
  std::map<int32_t, ArithExpr> expressions; ///< by expression index
  std::vector<Symbol> symbols;
  Sequential sequential;
  std::vector<std::string> files;    ///< every embedded file name, in file order
  std::vector<std::string> warnings; ///< accepted oddities (a cut expression, a long symbol)

  /// The expression of a compare/operate block (nullptr when the slot is absent).
  const ArithExpr *expression(int32_t index) const {
    auto it = expressions.find(index);
    return it == expressions.end() ? nullptr : &it->second;
  }
};

} // namespace lj::classicladder
