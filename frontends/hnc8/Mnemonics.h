// The HNC-8 spelling of the semantic operations: one row per mnemonic, with its alias, and the
// lookup the parser, the printer, the docs and the generator share.
#pragma once

#include "ir/OpTable.h"

#include <span>
#include <string_view>

namespace lj::hnc8 {

/// One mnemonic of the HNC-8 manual and the operation it spells.
struct MnemonicRow {
  Op op;
  const char *spelling; ///< upper case, as the manual writes it ("LD", "1END")
  const char *alias;    ///< a second accepted spelling (WRT, END1, END2), or nullptr
};

/// All rows, in Op order: one per operation HNC-8 spells. Operations only another dialect
/// spells (FANUC, IEC: ir/OpTable.h "dialect-only rows") have no row.
std::span<const MnemonicRow> mnemonicTable();

/// The row of `op`, or nullptr when HNC-8 does not spell it.
const MnemonicRow *mnemonicRow(Op op);

/// Whether the HNC-8 manual spells `op`.
inline bool spells(Op op) { return mnemonicRow(op) != nullptr; }

/// The manual's spelling of `op` ("LD"), or nullptr when HNC-8 does not spell it.
inline const char *spellingOf(Op op) {
  const MnemonicRow *r = mnemonicRow(op);
  return r ? r->spelling : nullptr;
}

/// The manual's spelling of `op` ("LD"); for an operation HNC-8 does not spell, its neutral
/// name (InstrInfo::name), so printing any program never fails.
inline const char *mnemonicOf(Op op) {
  const char *s = spellingOf(op);
  return s ? s : instrInfo(op).name;
}

/// Op spelled `mnemonic` (case-insensitive, aliases included).
bool lookupMnemonic(std::string_view mnemonic, Op &out);

} // namespace lj::hnc8
