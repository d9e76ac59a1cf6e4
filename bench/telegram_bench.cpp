// Cost of the telegram codec per frame: the part of every servo cycle spent on PROFIdrive bytes.
#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>

#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/normalisation.hpp"
#include "tomc/telegrams/sign_of_life.hpp"

namespace tg = tomc::telegrams;

namespace {

void BM_EncodeSetpoint(benchmark::State& state) {
  const auto codec =
      tg::TelegramCodec::create(static_cast<int>(state.range(0)), tg::Direction::kSetpoint).value();
  tg::SetpointSignals values;
  values.STW1 = tg::Stw1{0x047F};
  std::array<std::byte, tg::kMaxFrameBytes> frame{};
  const std::span out(frame.data(), codec.frame_size());
  double speed = 0.0;
  for (auto _ : state) {
    speed += 0.25;
    values.NSOLL_B = tg::speed_to_n4(speed, 3000.0);
    values.NSOLL_A = tg::speed_to_n2(speed, 3000.0);
    benchmark::DoNotOptimize(codec.encode(values, out));
    benchmark::ClobberMemory();
  }
}

void BM_DecodeActual(benchmark::State& state) {
  const auto codec =
      tg::TelegramCodec::create(static_cast<int>(state.range(0)), tg::Direction::kActual).value();
  std::array<std::byte, tg::kMaxFrameBytes> frame{};
  for (std::size_t i = 0; i < frame.size(); ++i)
    frame[i] = static_cast<std::byte>(i * 37);
  const std::span in(frame.data(), codec.frame_size());
  tg::ActualSignals values;
  for (auto _ : state) {
    frame[3] = static_cast<std::byte>(static_cast<unsigned>(frame[3]) + 1);
    benchmark::DoNotOptimize(codec.decode(in, values));
    benchmark::DoNotOptimize(values);
  }
}

// One servo cycle's protocol work for one axis on telegram 105: decode actual, state + sign-of-life checks,
// encode setpoint.
void BM_AxisCycleTelegram105(benchmark::State& state) {
  const auto setpoint = tg::TelegramCodec::create(105, tg::Direction::kSetpoint).value();
  const auto actual = tg::TelegramCodec::create(105, tg::Direction::kActual).value();
  std::array<std::byte, 20> in{};
  std::array<std::byte, 20> out{};
  tg::SetpointSignals sp;
  tg::ActualSignals act;
  tg::SignOfLifeGenerator master;
  tg::SignOfLifeMonitor slave_monitor;
  tg::Stw1Sequencer sequencer;
  tg::SignOfLifeGenerator slave;
  for (auto _ : state) {
    in[6] = static_cast<std::byte>(slave.next() << 4);  // ZSW2 sign-of-life, high byte bits 12..15
    (void)actual.decode(in, act);
    (void)slave_monitor.check(static_cast<std::uint8_t>(act.ZSW2.field(tg::kSignOfLifeField)));
    sp.STW1 = tg::Stw1{sequencer.next(act.ZSW1.value(), tg::DriveRequest::kOperate)};
    sp.STW2.set_field(tg::kSignOfLifeField, master.next());
    sp.NSOLL_B = tg::speed_to_n4(1500.0, 3000.0);
    sp.XERR = tg::xerr_from_counts(12.5);
    sp.KPC = tg::kpc_from_kv(500.0);
    (void)setpoint.encode(sp, out);
    benchmark::DoNotOptimize(out);
  }
}

}  // namespace

BENCHMARK(BM_EncodeSetpoint)->Arg(1)->Arg(3)->Arg(105)->Arg(106)->Arg(750);
BENCHMARK(BM_DecodeActual)->Arg(1)->Arg(3)->Arg(105)->Arg(106)->Arg(83);
BENCHMARK(BM_AxisCycleTelegram105);
