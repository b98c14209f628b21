// The call graph between subroutines: recursion is an error, the call nesting depth is limited
// (the main part is depth 0; dialect-notes "Flow"), and a subroutine no main part can reach is
// never called (a warning).
#include "verify/VerifierInternal.h"

namespace lj::verifier {

namespace {

std::string subName(const Context &cx, int32_t sub) {
  return std::string(cx.tp.area(Area::Subroutine).name) +
         std::to_string(cx.prog.subs[static_cast<size_t>(sub)].number);
}

} // namespace

void checkCallGraph(Context &cx) {
  const size_t nsubs = cx.prog.subs.size();
  std::vector<int32_t> unitOfSub(nsubs, -1);
  for (size_t u = 0; u < cx.units.size(); ++u)
    if (cx.units[u].kind == Unit::Kind::Sub)
      unitOfSub[static_cast<size_t>(cx.units[u].sub)] = static_cast<int32_t>(u);
  static const std::vector<CallSite> kNoCalls;
  auto callsOf = [&](int32_t sub) -> const std::vector<CallSite> & {
    int32_t u = unitOfSub[static_cast<size_t>(sub)];
    return u < 0 ? kNoCalls : cx.calls[static_cast<size_t>(u)];
  };

  // Iterative depth-first search (no native recursion: 512 nested subroutines must not
  // overflow the C++ stack). height = levels of calls a CALL of this subroutine adds.
  enum : uint8_t { White, Gray, Black };
  std::vector<uint8_t> color(nsubs, White);
  std::vector<int32_t> height(nsubs, 1);
  bool recursion = false;
  std::vector<std::pair<int32_t, size_t>> stack;
  for (size_t root = 0; root < nsubs; ++root) {
    if (color[root] != White) continue;
    color[root] = Gray;
    stack.push_back({static_cast<int32_t>(root), 0});
    while (!stack.empty()) {
      auto &[sub, next] = stack.back();
      const std::vector<CallSite> &edges = callsOf(sub);
      if (next < edges.size()) {
        const CallSite &e = edges[next++];
        auto c = static_cast<size_t>(e.callee);
        if (color[c] == Gray) {
          recursion = true;
          std::string path;
          bool on = false;
          for (const auto &fr : stack) {
            on = on || static_cast<size_t>(fr.first) == c;
            if (on) path += subName(cx, fr.first) + " -> ";
          }
          path += subName(cx, e.callee);
          cx.error(cx.stmt(e.stmt).loc, "LJ1001", "recursion: " + path);
        } else if (color[c] == White) {
          color[c] = Gray;
          stack.push_back({e.callee, 0});
        } else {
          height[static_cast<size_t>(sub)] =
              std::max(height[static_cast<size_t>(sub)], 1 + height[c]);
        }
        continue;
      }
      int32_t done = sub;
      color[static_cast<size_t>(done)] = Black;
      stack.pop_back();
      if (!stack.empty()) {
        auto parent = static_cast<size_t>(stack.back().first);
        height[parent] = std::max(height[parent], 1 + height[static_cast<size_t>(done)]);
      }
    }
  }

  // Reachability from the main parts, and the depth of each CALL made there.
  std::vector<bool> reached(nsubs, false);
  std::vector<int32_t> work;
  for (size_t u = 0; u < cx.units.size(); ++u) {
    if (cx.units[u].kind == Unit::Kind::Sub) continue;
    for (const CallSite &e : cx.calls[u]) {
      auto c = static_cast<size_t>(e.callee);
      if (!recursion && height[c] > *cx.opts.maxCallDepth)
        cx.error(cx.stmt(e.stmt).loc, "LJ1002",
                 "call nesting depth " + std::to_string(height[c]) + " exceeds the limit of " +
                     std::to_string(*cx.opts.maxCallDepth));
      if (!reached[c]) {
        reached[c] = true;
        work.push_back(e.callee);
      }
    }
  }
  while (!work.empty()) {
    int32_t s = work.back();
    work.pop_back();
    for (const CallSite &e : callsOf(s)) {
      if (!reached[static_cast<size_t>(e.callee)]) {
        reached[static_cast<size_t>(e.callee)] = true;
        work.push_back(e.callee);
      }
    }
  }
  for (size_t s = 0; s < nsubs; ++s) {
    const Subroutine &sub = cx.prog.subs[s];
    bool primary = cx.prog.subByNumber[static_cast<size_t>(sub.number)] == static_cast<int32_t>(s);
    if (!reached[s] && primary)
      cx.warning(cx.stmt(sub.spIndex).loc, "LJ1003",
                 "subroutine " + subName(cx, static_cast<int32_t>(s)) + " is never called");
  }
}

} // namespace lj::verifier
