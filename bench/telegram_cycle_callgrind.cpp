// Fixed workload for callgrind: the telegram part of one axis' servo cycle on telegram 105 (decode actual,
// sign-of-life check, STW1 sequencing, encode setpoint), run kCycles times. scripts/bench divides the
// instructions counted inside telegram_cycle() by kCycles.
#include <array>
#include <cstddef>
#include <cstdio>

#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/normalisation.hpp"
#include "tomc/telegrams/sign_of_life.hpp"

namespace tg = tomc::telegrams;

constexpr int kCycles = 100000;

struct Axis {
  tg::TelegramCodec setpoint = tg::TelegramCodec::create(105, tg::Direction::kSetpoint).value();
  tg::TelegramCodec actual = tg::TelegramCodec::create(105, tg::Direction::kActual).value();
  std::array<std::byte, 20> in{};
  std::array<std::byte, 20> out{};
  tg::SetpointSignals sp;
  tg::ActualSignals act;
  tg::SignOfLifeGenerator master;
  tg::SignOfLifeGenerator slave;
  tg::SignOfLifeMonitor monitor;
  tg::Stw1Sequencer sequencer;
};

extern "C" __attribute__((noinline)) void telegram_cycle(Axis& a, double speed) {
  a.in[6] = static_cast<std::byte>(a.slave.next() << 4);
  (void)a.actual.decode(a.in, a.act);
  (void)a.monitor.check(static_cast<std::uint8_t>(a.act.ZSW2.field(tg::kSignOfLifeField)));
  a.sp.STW1 = tg::Stw1{a.sequencer.next(a.act.ZSW1.value(), tg::DriveRequest::kOperate)};
  a.sp.STW2.set_field(tg::kSignOfLifeField, a.master.next());
  a.sp.NSOLL_B = tg::speed_to_n4(speed, 3000.0);
  a.sp.XERR = tg::xerr_from_counts(speed * 0.01);
  a.sp.KPC = tg::kpc_from_kv(500.0);
  (void)a.setpoint.encode(a.sp, a.out);
}

int main() {
  Axis axis;
  for (int i = 0; i < kCycles; ++i)
    telegram_cycle(axis, 0.01 * i);
  std::printf("cycles=%d last=%02x\n", kCycles, static_cast<unsigned>(axis.out[3]));
  return 0;
}
