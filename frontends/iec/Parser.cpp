// The IEC IL (Neza) parser: lines `[NNN] MNEMONIC [operand]`, `%Li :` labels, `SRi :`
// subroutine entries, `[ ... ]` operation blocks, `(* ... *)` comments (modicon-neza.md 1.3, 7),
// with every restriction the seed states as a located error (2.8, 2.9, 9) and the
// non-reversible forms (9 rule 3, rule 8) as warnings. The IR mapping is Emitter.h's;
// the parser's parts are ParserInternal.h's files.
#include "frontends/iec/FrontEnd.h"
#include "frontends/iec/ParserInternal.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

namespace lj::iec::detail {

void IlParser::run(std::string_view text) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  // The init part: the block presets go before its end marker once the program is read (the
  // runtime writes %S0 / %S1 and the clocks: profiles/iec/Areas.cpp).
  em_.emit(Op::EndInit, {1, 1});
  int32_t lineNo = 0;
  size_t pos = 0;
  while (pos <= text.size() && diags_.errorCount() < kMaxErrors) {
    size_t nl = text.find('\n', pos);
    std::string_view line =
        text.substr(pos, nl == std::string_view::npos ? text.size() - pos : nl - pos);
    ++lineNo;
    handleLine(line, lineNo);
    if (nl == std::string_view::npos) break;
    pos = nl + 1;
  }
  // Lines without statements at the end (an END_BLK after OUT_BLK) go with the last line that
  // has statements.
  if (!pendingWritten_.empty() && lastFirst_ < prog_.stmts.size()) {
    if (prog_.written.empty() || prog_.written.back().first != static_cast<int32_t>(lastFirst_))
      prog_.written.push_back({static_cast<int32_t>(lastFirst_),
                               static_cast<int32_t>(prog_.stmts.size() - lastFirst_), lastText_});
    prog_.written.back().text += "\n" + pendingWritten_;
    pendingWritten_.clear();
  }
  const SourceLoc end{lineNo, 1};
  if (inComment_) diags_.error(commentLoc_, "LJ2022", "comment '(*' is not closed by '*)'");
  blocks_.mustBeClosed(end, "the end of the program");
  closeSequence(end, "the end of the program");
  if (!mainDone_) finishMain(end);
  if (sub_ >= 0) em_.emit(Op::SubEnd, end);
  insertPresets();
}

void IlParser::record(size_t first, std::string_view code, int32_t line) {
  const size_t n = prog_.stmts.size() - first;
  while (!code.empty() && blank(code.front())) code.remove_prefix(1);
  while (!code.empty() && blank(code.back())) code.remove_suffix(1);
  if (n == 0) {
    if (pendingWritten_.empty()) pendingLine_ = line;
    pendingWritten_ += (pendingWritten_.empty() ? "" : "\n") + std::string(code);
    return;
  }
  lastFirst_ = first;
  lastText_ = code;
  bool need = !pendingWritten_.empty();
  for (size_t i = first; i < prog_.stmts.size() && !need; ++i) {
    const Stmt &s = prog_.stmts[i];
    need = s.op == Op::IecTimer || s.op == Op::IecCounter;
    for (int k = 0; k < s.operandCount && !need; ++k) {
      const Operand &o = s.ops[static_cast<size_t>(k)];
      need = o.area == Area::ExtraRelay ||
             (s.op == Op::Jump && o.area == Area::Label && o.index == kEndLabel);
    }
  }
  if (!need) return;
  const int32_t from = pendingWritten_.empty() ? 0 : pendingLine_;
  std::string text =
      pendingWritten_.empty() ? std::string(code) : pendingWritten_ + "\n" + std::string(code);
  pendingWritten_.clear();
  prog_.written.push_back(
      {static_cast<int32_t>(first), static_cast<int32_t>(n), std::move(text), from});
}

void IlParser::insertPresets() {
  std::vector<Stmt> pre = blocks_.presets({1, 1});
  if (pre.empty()) return;
  // Made from the blocks' configuration on every read: written as nothing of their own.
  for (WrittenInstr &w : prog_.written) w.first += static_cast<int32_t>(pre.size());
  prog_.written.insert(prog_.written.begin(), {0, static_cast<int32_t>(pre.size()), {}});
  prog_.stmts.insert(prog_.stmts.begin(), pre.begin(), pre.end());
  for (size_t i = 0; i < prog_.stmts.size(); ++i) prog_.stmts[i].id = static_cast<StmtId>(i);
  for (Comment &c : prog_.comments) c.stmt += static_cast<int32_t>(pre.size());
}

void IlParser::handleLine(std::string_view line, int32_t lineNo) {
  // Remove (* ... *) comments (they may span lines), keep their text.
  std::string code(line.size(), ' ');
  std::string comment;
  bool hadComment = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (inComment_) {
      if (line.compare(i, 2, "*)") == 0) {
        inComment_ = false;
        ++i;
      } else {
        comment += line[i];
      }
      continue;
    }
    if (line.compare(i, 2, "(*") == 0) {
      inComment_ = true;
      hadComment = true;
      commentLoc_ = {lineNo, static_cast<int32_t>(i) + 1};
      ++i;
      continue;
    }
    code[i] = line[i];
  }
  if (!comment.empty()) hadComment = true; // the middle and last lines of a long (* ... *)
  const size_t before = prog_.stmts.size();
  bool hasCode = false;
  for (char c : code)
    if (!blank(c)) hasCode = true;
  if (hasCode) {
    statement(code, lineNo);
    record(before, code, lineNo);
  }
  if (hadComment) {
    while (!comment.empty() && blank(comment.back())) comment.pop_back();
    size_t b = 0;
    while (b < comment.size() && blank(comment[b])) ++b;
    prog_.comments.push_back({lineNo, static_cast<int32_t>(hasCode ? before : prog_.stmts.size()),
                              hasCode, comment.substr(b)});
  }
}

void IlParser::statement(const std::string &code, int32_t lineNo) {
  size_t i = 0;
  auto skip = [&] {
    while (i < code.size() && blank(code[i])) ++i;
  };
  auto at = [&](size_t k) { return SourceLoc{lineNo, static_cast<int32_t>(k) + 1}; };
  skip();
  // The auto-generated statement number `003` (L308-315).
  size_t d = i;
  while (d < code.size() && std::isdigit(static_cast<unsigned char>(code[d]))) ++d;
  if (d > i && d < code.size() && blank(code[d])) {
    i = d;
    skip();
  }
  size_t endCode = code.size();
  while (endCode > i && blank(code[endCode - 1])) --endCode;
  std::string_view rest(code.data() + i, endCode - i);
  const SourceLoc loc = at(i);
  if (rest.empty()) return;
  const std::string up = upper(rest);
  if (stmtCount_++ >= kStatementLimit) {
    if (stmtCount_ == kStatementLimit + 1)
      error(loc, "LJ2023",
            "program has more than " + std::to_string(kStatementLimit) + " instructions");
    return;
  }
  // `%Li :` and `SRi :` headers.
  if (size_t colon = rest.find(':'); colon != std::string_view::npos &&
                                     (up.rfind("%L", 0) == 0 || up.rfind("SR", 0) == 0) &&
                                     rest.find(":=") == std::string_view::npos) {
    std::string_view name = rest.substr(0, colon);
    while (!name.empty() && blank(name.back())) name.remove_suffix(1);
    std::string_view after = rest.substr(colon + 1);
    while (!after.empty() && blank(after.front())) after.remove_prefix(1);
    if (!after.empty() && upper(after).rfind("X", 0) != 0) {
      error(at(i + colon + 1), "LJ2024", "a label or subroutine header stands on its own line");
      return;
    }
    if (after.empty()) {
      header(name, loc);
      return;
    }
  }
  if (rest.front() == '[') {
    operationBlock(rest, loc);
    return;
  }
  if (rest.front() == ')') {
    if (rest.size() > 1) {
      error(at(i + 1), "LJ2025", "unexpected text after ')'");
      return;
    }
    closeParen(loc);
    return;
  }
  size_t m = 0;
  while (m < rest.size() && (std::isalnum(static_cast<unsigned char>(rest[m])) || rest[m] == '_'))
    ++m;
  if (m == 0) {
    error(loc, "LJ2026",
          "expected an instruction, found '" + std::string(rest.substr(0, 20)) + "'");
    return;
  }
  std::string mnem = upper(rest.substr(0, m));
  std::optional<char> paren; // AND( / OR( and their modifier ('\0' none, N R F or '[')
  size_t k = m;
  if (k < rest.size() && rest[k] == '(') {
    ++k;
    char mod = '\0';
    if (k < rest.size()) {
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(rest[k])));
      if (c == 'N' || c == 'R' || c == 'F') {
        mod = c;
        ++k;
      } else if (c == '[') {
        mod = '[';
      }
    }
    paren = mod;
  }
  while (k < rest.size() && blank(rest[k])) ++k;
  const SourceLoc opLoc = at(i + k);
  instruction(mnem, paren, rest.substr(k), loc, opLoc);
}

void IlParser::instruction(const std::string &mnem, std::optional<char> paren,
                           std::string_view text, SourceLoc loc, SourceLoc opLoc) {
  // The load family: LD LDN LDR LDF.
  static const std::pair<const char *, Mod> kLoads[] = {
      {"LD", Mod::Plain}, {"LDN", Mod::Not}, {"LDR", Mod::Rise}, {"LDF", Mod::Fall}};
  static const std::pair<const char *, Mod> kMods[] = {
      {"", Mod::Plain}, {"N", Mod::Not}, {"R", Mod::Rise}, {"F", Mod::Fall}};
  if (!paren && blockInstruction(mnem, text, loc, opLoc)) return;
  if (blocks_.section() == FunctionBlocks::Section::Inputs && !paren && !testInstruction(mnem)) {
    inputSection(loc, mnem);
    return;
  }
  if (paren) {
    if (mnem != "AND" && mnem != "OR") {
      error(loc, "LJ2027", "only AND( and OR( open a parenthesis, found '" + mnem + "('");
      return;
    }
    if (!needSequence(loc, mnem + "(")) return;
    if (static_cast<int32_t>(parens_.size()) >= kParenDepth) {
      error(loc, "LJ2028",
            mnem + "( nests parentheses deeper than " + std::to_string(kParenDepth) +
                " levels (modicon-neza.md 2.8, L924-925)");
      return;
    }
    if (!mps_.empty() && parens_.empty()) {
      // MPS entries stay outside; nothing to check here.
    }
    const Mod mod = *paren == 'N'   ? Mod::Not
                    : *paren == 'R' ? Mod::Rise
                    : *paren == 'F' ? Mod::Fall
                                    : Mod::Plain;
    parens_.push_back({mnem == "AND" ? Op::AndBlock : Op::OrBlock, loc});
    pushTest(mnem + "(" + (*paren && *paren != '[' ? std::string(1, *paren) : ""), mod, text, loc,
             opLoc, true);
    return;
  }
  for (const auto &[name, mod] : kLoads)
    if (mnem == name) {
      startSequence(loc, mnem);
      pushTest(mnem, mod, text, loc, opLoc, mod == Mod::Plain || mod == Mod::Not);
      return;
    }
  // AND / OR / XOR families.
  for (const char *fam : {"AND", "OR", "XOR"})
    for (const auto &[suffix, mod] : kMods) {
      if (mnem != std::string(fam) + suffix) continue;
      combine(fam, mod, mnem, text, loc, opLoc);
      return;
    }
  if (mnem == "ST" || mnem == "STN" || mnem == "S" || mnem == "R") {
    coil(mnem, text, loc, opLoc);
    return;
  }
  if (mnem == "N") {
    if (!needSequence(loc, mnem)) return;
    if (!text.empty()) error(opLoc, "LJ2029", "N takes no operand");
    nonReversible(loc, "N");
    em_.negate(loc);
    return;
  }
  if (mnem == "MPS" || mnem == "MRD" || mnem == "MPP") {
    branch(mnem, text, loc);
    return;
  }
  if (mnem == "JMP" || mnem == "JMPC" || mnem == "JMPCN") {
    jump(mnem, text, loc, opLoc);
    return;
  }
  if (mnem == "END" || mnem == "ENDC" || mnem == "ENDCN") {
    end(mnem, text, loc, opLoc);
    return;
  }
  if (mnem == "RET" || mnem == "RETC" || mnem == "RETCN") {
    ret(mnem, text, loc, opLoc);
    return;
  }
  if (mnem.size() > 2 && mnem.rfind("SR", 0) == 0 &&
      mnem.find_first_not_of("0123456789", 2) == std::string::npos) {
    call(mnem, text, loc, opLoc);
    return;
  }
  if (mnem == "NOP") {
    if (!text.empty()) error(opLoc, "LJ2030", "NOP takes no operand");
    return;
  }
  static const char *const kBlocks[] = {"I", "O", "DS", "RET_BLK"};
  for (const char *b : kBlocks)
    if (mnem == b) {
      error(loc, "LJ2031",
            mnem + ": an input of the %Ri / %DRi / %SBRi / %SCi blocks, which are not "
                   "supported (their pages are missing from the seed; docs/iec-il.md)");
      return;
    }
  error(loc, "LJ2032", "unknown instruction '" + mnem + "'");
}

} // namespace lj::iec::detail

namespace lj::iec {

ParsedProgram parseIl(std::string_view text, std::string file, Diagnostics &diags) {
  ParsedProgram prog;
  prog.file = std::move(file);
  prog.dialect = &dialectText();
  prog.profile = &profile();
  detail::IlParser(prog, diags).run(text);
  return prog;
}

} // namespace lj::iec
