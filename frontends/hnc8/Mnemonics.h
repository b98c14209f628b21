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

/// All rows, in Op order (one per operation).
std::span<const MnemonicRow> mnemonicTable();

/// The row of `op`.
const MnemonicRow &mnemonicRow(Op op);

/// The manual's spelling of `op` ("LD").
inline const char *mnemonicOf(Op op) { return mnemonicRow(op).spelling; }

/// Op spelled `mnemonic` (case-insensitive, aliases included).
bool lookupMnemonic(std::string_view mnemonic, Op &out);

} // namespace lj::hnc8
