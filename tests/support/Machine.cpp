// Compiling test programs and driving one engine tick by tick.
#include "tests/support/Machine.h"
#include "pipeline/Compile.h"

#include "tests/support/TestAddress.h"

#include "hosts/SystemBits.h"

#include <gtest/gtest.h>

namespace lj::test {

VerifyOptions optionsWithNvalue(int32_t plc2Nvalue) {
  VerifyOptions o;
  o.plc2Nvalue = plc2Nvalue;
  return o;
}

std::optional<VerifiedProgram> compileOrFail(std::string_view text, const VerifyOptions &opts) {
  Diagnostics diags("test.stl");
  std::optional<VerifiedProgram> prog = pipeline::compileStl(text, "test.stl", opts, diags);
  if (!prog || diags.hasErrors()) {
    ADD_FAILURE() << "program does not verify:\n" << diags.render() << "--- program ---\n" << text;
    return std::nullopt;
  }
  return prog;
}

std::unique_ptr<Machine> Machine::load(std::string_view text, const EngineFactory &engine,
                                       const VerifyOptions &opts) {
  std::optional<VerifiedProgram> prog = compileOrFail(text, opts);
  if (!prog) return nullptr;
  return create(*prog, engine);
}

std::unique_ptr<Machine> Machine::create(const VerifiedProgram &prog, const EngineFactory &engine) {
  std::unique_ptr<Machine> m(new Machine());
  m->prog_ = std::make_unique<VerifiedProgram>(prog);
  std::string error;
  m->engine_ = engine.make(*m->prog_, error);
  if (!m->engine_) {
    ADD_FAILURE() << "engine '" << engine.name << "' failed to build: " << error;
    return nullptr;
  }
  m->state_ = std::make_unique<lj_state>();
  lj_state_reset(m->state_.get());
  return m;
}

uint32_t Machine::init() {
  state_->now_ms = 0;
  return lj_run_init(state_.get(), &engine_->entries());
}

uint32_t Machine::tick() {
  state_->now_ms = static_cast<uint64_t>(tick_) * periodMs_;
  hosts::writeSystemBits(*prog_->profile, *state_, tick_); // FANUC R9091/R9015 (none for HNC-8)
  ++tick_;
  return lj_tick(state_.get(), &engine_->entries());
}

uint32_t Machine::ticks(uint32_t n) {
  uint32_t fault = LJ_FAULT_NONE;
  for (uint32_t i = 0; i < n; ++i) fault = tick();
  return fault;
}

uint32_t Machine::tick(const Scenario &sc) {
  for (const Stimulus &st : sc.inputs)
    if (st.tick == tick_) set(st.addr, st.value);
  if (sc.hostInputs) sc.hostInputs(tick_, *state_);
  return tick();
}

int64_t Machine::get(std::string_view addr) const { return readAddr(*state_, parseTestAddr(addr)); }

void Machine::set(std::string_view addr, int64_t value) {
  writeAddr(*state_, parseTestAddr(addr), value);
}

} // namespace lj::test
