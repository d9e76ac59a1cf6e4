// `tomc telegram` end to end: every spec 06 §11 vector that is a frame goes through the CLI, plus round trips
// and the error exits (status 2, one line on stderr).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include "build_paths.hpp"

namespace {

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

CliRun tomc(const std::vector<std::string>& args) {
  // One file per process: ctest runs the test cases of this binary in parallel.
  const std::string err_file = ::testing::TempDir() + "tomc_cli_stderr_" + std::to_string(getpid()) + ".txt";
  std::string cmd = shell_quote(TOMC_BINARY);
  for (const auto& a : args)
    cmd += " " + shell_quote(a);
  cmd += " 2>" + shell_quote(err_file);
  CliRun run;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return run;
  char buf[4096];
  std::size_t n = 0;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0)
    run.out.append(buf, n);
  const int status = pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  std::stringstream ss;
  ss << err.rdbuf();
  run.err = ss.str();
  return run;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
    s.pop_back();
  return s;
}

struct EncodeCase {
  const char* vector;
  std::vector<std::string> args;
  const char* expected_hex;
};

// spec 06 §11: every setpoint-frame vector, encoded from JSON given the way a commissioning engineer writes
// it.
TEST(CliEncode, SpecVectors) {
  const std::vector<EncodeCase> cases = {
      {"TV01",
       {"--telegram", "1", "--reference-speed", "3000", R"({"STW1":"0x047F","NSOLL_A":{"speed":1500}})"},
       "04 7F 20 00"},
      {"TV02",
       {"--telegram", "1", "--reference-speed", "3000", R"({"STW1":"0x047E","NSOLL_A":{"speed":-750}})"},
       "04 7E F0 00"},
      {"TV03",
       {"--telegram", "2", "--reference-speed", "3000",
        R"({"STW1":"0x047F","NSOLL_B":{"speed":1500},"STW2":{"SignOfLife":1}})"},
       "04 7F 20 00 00 00 10 00"},
      {"TV04",
       {"--telegram", "3", "--reference-speed", "3000",
        R"({"STW1":"0x047F","NSOLL_B":{"speed":1500},"STW2":{"SignOfLife":5},"G1_STW":0})"},
       "04 7F 20 00 00 00 50 00 00 00"},
      {"TV07",
       {"--telegram", "2", "--reference-speed", "3000", R"({"NSOLL_B":{"speed":-3000}})"},
       "00 00 C0 00 00 00 00 00"},
      {"TV08 233 %",
       {"--telegram", "2", "--reference-speed", "3000", R"({"NSOLL_B":{"speed":7000}})"},
       "00 00 7F FF FF FF 00 00"},
      {"TV08 200 %",
       {"--telegram", "2", "--reference-speed", "3000", R"({"NSOLL_B":{"speed":6000}})"},
       "00 00 7F FF FF FF 00 00"},
      {"TV09",
       {"--telegram", "102", "--reference-speed", "3000",
        R"({"STW1":"0x047F","NSOLL_B":{"speed":1500},"STW2":{"SignOfLife":3},"MOMRED":{"reduction_percent":75},"G1_STW":0})"},
       "04 7F 20 00 00 00 30 00 30 00 00 00"},
      {"TV10",
       {"--telegram", "105", "--reference-speed", "3000",
        R"({"STW1":"0x047F","NSOLL_B":{"speed":1500},"STW2":{"SignOfLife":1},"MOMRED":0,"G1_STW":0,"XERR":-1234,"KPC":{"kv":500}})"},
       "04 7F 20 00 00 00 10 00 00 00 00 00 FF FF FB 2E 00 07 A1 20"},
      {"TV11",
       {"--telegram", "5", R"({"KPC":{"kv":666.6666666667}})"},
       "00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 0A 2C 2B"},
      {"TV14",
       {"--telegram", "750", R"({"M_ADD1":0,"M_LIMIT_POS":"0x4000","M_LIMIT_NEG":-16384})"},
       "00 00 40 00 C0 00"},
      {"TV15",
       {"--telegram", "750", "--reference-torque", "10",
        R"({"M_ADD":{"torque":2.5},"M_LIMIT_POS":{"torque":5},"M_LIMIT_NEG":{"torque":-5}})"},
       "10 00 20 00 E0 00"},
      {"TV17",
       {"--telegram", "2", R"({"STW2":{"value":"0x0100","SignOfLife":14}})"},
       "00 00 00 00 00 00 E1 00"},
      {"TV23 reference-mark search",
       {"--telegram", "3", R"({"G1_STW":{"Function1":true,"Command":1}})"},
       "00 00 00 00 00 00 00 00 00 11"},
      {"TV23 flying measurement",
       {"--telegram", "3", R"({"G1_STW":{"Function1":true,"Command":1,"MeasurementMode":true}})"},
       "00 00 00 00 00 00 00 00 00 91"},
      {"TV23 acknowledge",
       {"--telegram", "3", R"({"G1_STW":{"AcknowledgeEncoderError":true}})"},
       "00 00 00 00 00 00 00 00 80 00"},
      {"TV26 acknowledge word",
       {"--telegram", "1", R"({"STW1":{"value":"0x047E","AcknowledgeFault":true}})"},
       "04 FE 00 00"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"telegram", "encode", "--direction", "setpoint"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const CliRun r = tomc(args);
    EXPECT_EQ(r.status, 0) << c.vector << ": " << r.err;
    EXPECT_EQ(trimmed(r.out), c.expected_hex) << c.vector;
  }
}

nlohmann::json decode(const std::vector<std::string>& args) {
  std::vector<std::string> full = {"telegram", "decode"};
  full.insert(full.end(), args.begin(), args.end());
  const CliRun r = tomc(full);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

// spec 06 §11 TV05
TEST(CliDecode, TV05Telegram3Actual) {
  const auto j = decode({"--telegram", "3", "--direction", "actual", "--reference-speed", "3000",
                         "02 37 E0 00 00 00 60 00 00 00 00 40 00 00 00 00 00 00"});
  EXPECT_EQ(j["signals"]["ZSW1"]["value"], 0x0237);
  EXPECT_EQ(j["derived"]["drive_state"], "S4");
  EXPECT_EQ(j["signals"]["NIST_B"], static_cast<int32_t>(0xE0000000u));
  EXPECT_DOUBLE_EQ(j["derived"]["NIST_B"]["speed"].get<double>(), -1500.0);
  EXPECT_EQ(j["signals"]["ZSW2"]["bits"]["SignOfLife"], 6);
  EXPECT_EQ(j["signals"]["G1_ZSW"]["value"], 0);
  EXPECT_EQ(j["signals"]["G1_XIST1"], 4194304);
  EXPECT_EQ(j["signals"]["G1_XIST2"], 0);
  EXPECT_EQ(j["derived"]["G1_XIST2"]["content"], "not valid");
}

// spec 06 §11 TV06: NIST_B 0x0CCCCCCD = 0.2000000002 x 3000 rpm
TEST(CliDecode, TV06NistB) {
  const auto j = decode(
      {"--telegram", "2", "--direction", "actual", "--reference-speed", "3000", "00 00 0C CC CC CD 00 00"});
  EXPECT_NEAR(j["derived"]["NIST_B"]["speed"].get<double>(), 600.0000006, 1e-7);
}

// spec 06 §11 TV08: raw 0x80000000 decodes to -6000 rpm
TEST(CliDecode, TV08MostNegative) {
  const auto j = decode(
      {"--telegram", "2", "--direction", "actual", "--reference-speed", "3000", "00 00 80 00 00 00 00 00"});
  EXPECT_DOUBLE_EQ(j["derived"]["NIST_B"]["speed"].get<double>(), -6000.0);
}

// spec 06 §11 TV13
TEST(CliDecode, TV13Telegram105Actual) {
  const auto j = decode({"--telegram", "105", "--direction", "actual", "--reference-speed", "3000",
                         "02 37 10 00 00 00 20 00 30 00 20 00 12 34 56 78 01 00 00 00"});
  EXPECT_EQ(j["derived"]["drive_state"], "S4");
  EXPECT_DOUBLE_EQ(j["derived"]["NIST_B"]["speed"].get<double>(), 750.0);
  EXPECT_EQ(j["signals"]["ZSW2"]["bits"]["SignOfLife"], 2);
  EXPECT_EQ(j["signals"]["MELDW"]["bits"]["DriveReady"], true);
  EXPECT_EQ(j["signals"]["MELDW"]["bits"]["PulsesEnabled"], true);
  EXPECT_EQ(j["signals"]["MELDW"]["bits"]["ControllerEnable"], false);
  EXPECT_EQ(j["signals"]["G1_ZSW"]["bits"]["AbsoluteValueTransmitted"], true);
  EXPECT_EQ(j["derived"]["G1_XIST2"]["content"], "absolute value");
  EXPECT_EQ(j["signals"]["G1_XIST1"], 0x12345678);
  EXPECT_EQ(j["signals"]["G1_XIST2"], 0x01000000);
}

// spec 06 §11 TV16: M_ACT 0xF800 with T_ref 10 Nm = -1.25 Nm
TEST(CliDecode, TV16ActualTorque) {
  const auto j = decode({"--telegram", "750", "--direction", "actual", "--reference-torque", "10", "F800"});
  EXPECT_EQ(j["signals"]["M_ACT"], -2048);
  EXPECT_DOUBLE_EQ(j["derived"]["M_ACT"]["torque"].get<double>(), -1.25);
}

// spec 06 §11 TV22: G1_ZSW.15 -> XIST2 holds error code 1, sensor group error
TEST(CliDecode, TV22EncoderError) {
  const auto j = decode({"--telegram", "81", "--direction", "actual", "00 00 80 00 00 00 00 00 00 00 00 01"});
  EXPECT_EQ(j["derived"]["G1_XIST2"]["content"], "error code");
  EXPECT_EQ(j["derived"]["G1_XIST2"]["error_code"], "0x0001");
  EXPECT_EQ(j["derived"]["G1_XIST2"]["error"], "sensor group error (position cannot be read)");
}

// spec 06 §11 TV24: drive state from ZSW1, through the telegram 1 actual frame
TEST(CliDecode, TV24DriveStates) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"02 70", "S1"},  {"02 31", "S2"},    {"02 33", "S3"}, {"02 37", "S4"},
      {"02 13", "S5b"}, {"02 48", "FAULT"}, {"00 37", "S4"}};
  for (const auto& [zsw1, state] : cases) {
    const auto j = decode({"--telegram", "1", "--direction", "actual", zsw1 + " 00 00"});
    EXPECT_EQ(j["derived"]["drive_state"], state) << zsw1;
    EXPECT_EQ(j["derived"]["control_requested"], zsw1 != "00 37") << zsw1;
  }
}

// spec 06 §11 TV25: encoder telegrams 81 and 83
TEST(CliDecode, TV25EncoderTelegrams) {
  const auto t81 =
      decode({"--telegram", "81", "--direction", "actual", "12 00 00 00 00 AB CD EF 00 00 00 00"});
  EXPECT_EQ(t81["signals"]["ZSW2_ENC"]["bits"]["ControlRequested"], true);
  EXPECT_EQ(t81["signals"]["ZSW2_ENC"]["bits"]["SignOfLife"], 1);
  EXPECT_EQ(t81["signals"]["G1_ZSW"]["value"], 0);
  EXPECT_EQ(t81["signals"]["G1_XIST1"], 0x00ABCDEF);
  const auto t83 = decode({"--telegram", "83", "--direction", "actual", "--reference-speed", "3000",
                           "12 00 20 00 00 AB CD EF 00 12 34 56 06 66 66 66"});
  EXPECT_EQ(t83["derived"]["G1_XIST2"]["content"], "absolute value");
  EXPECT_EQ(t83["signals"]["G1_XIST2"], 0x00123456);
  EXPECT_NEAR(t83["derived"]["NIST_B"]["speed"].get<double>(), 299.9999989, 1e-6);
}

// The NIST_B position of telegram 83 is a connection option (spec 06 §2.13 [UNCONFIRMED]).
TEST(CliDecode, Telegram83NistBOffset) {
  const auto j = decode({"--telegram", "83", "--direction", "actual", "--nist-b-offset", "4",
                         "12 00 20 00 06 66 66 66 00 AB CD EF 00 12 34 56"});
  EXPECT_EQ(j["signals"]["NIST_B"], 0x06666666);
  EXPECT_EQ(j["signals"]["G1_XIST1"], 0x00ABCDEF);
  EXPECT_EQ(j["signals"]["G1_XIST2"], 0x00123456);
}

// Byte order per connection (spec 06 §1.1): the same TV01 frame as a little-endian gateway presents it.
TEST(CliDecode, ByteOrderOption) {
  const auto j = decode(
      {"--telegram", "2", "--direction", "setpoint", "--byte-order", "little", "7F 04 00 00 00 20 00 10"});
  EXPECT_EQ(j["signals"]["STW1"]["value"], 0x047F);
  EXPECT_EQ(j["signals"]["NSOLL_B"], 0x20000000);
  EXPECT_EQ(j["signals"]["STW2"]["bits"]["SignOfLife"], 1);
}

class CliRoundTrip : public ::testing::TestWithParam<int> {};

// decode(encode(x)) == x for every telegram and direction, with all signals set by raw value (spec 06 §2:
// the layouts of every telegram). One ctest entry per telegram, so that `ctest -j2` balances its 78 runs of
// the program (decision V14).
TEST_P(CliRoundTrip, BothDirections) {
  const std::string telegram = std::to_string(GetParam());
  for (const char* direction : {"setpoint", "actual"}) {
    const CliRun layout = tomc({"telegram", "layout", "--telegram", telegram, "--direction", direction});
    ASSERT_EQ(layout.status, 0) << layout.err;
    const auto fields = nlohmann::json::parse(layout.out)["fields"];
    nlohmann::json input = nlohmann::json::object();
    int k = 1;
    for (const auto& f : fields) {
      const int bits = f["bits"];
      input[f["signal"].get<std::string>()] = bits == 16 ? 0x1234 + 0x111 * k : 0x01020304 + 0x01010101 * k;
      ++k;
    }
    const CliRun enc =
        tomc({"telegram", "encode", "--telegram", telegram, "--direction", direction, input.dump()});
    ASSERT_EQ(enc.status, 0) << telegram << " " << direction << ": " << enc.err;
    const auto j = decode({"--telegram", telegram, "--direction", direction, trimmed(enc.out)});
    for (const auto& [name, value] : input.items()) {
      const auto& got = j["signals"][name];
      const long long actual = got.is_object() ? got["value"].get<long long>() : got.get<long long>();
      EXPECT_EQ(actual, value.get<long long>()) << telegram << " " << direction << " " << name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTelegram, CliRoundTrip,
                         ::testing::Values(1, 2, 3, 4, 5, 6, 81, 83, 102, 103, 105, 106, 750));

struct ErrorCase {
  const char* what;
  std::vector<std::string> args;
  const char* message_part;
};

// Bad input -> one line on stderr, exit status 2, nothing on stdout.
// README.md "`tomc telegram`: decode a captured frame, build one by hand" (bad input: status 2); spec 06 §2.
TEST(CliErrors, ExitTwoWithOneLine) {
  const std::vector<ErrorCase> cases = {
      {"unknown telegram",
       {"telegram", "decode", "--telegram", "7", "--direction", "actual", "0000"},
       "unknown telegram"},
      {"telegram 104", {"telegram", "decode", "--telegram", "104", "--direction", "actual", "0000"}, "104"},
      {"wrong length",
       {"telegram", "decode", "--telegram", "1", "--direction", "actual", "02 37 00"},
       "4 bytes, got 3"},
      {"bad hex",
       {"telegram", "decode", "--telegram", "1", "--direction", "actual", "02 3z 00 00"},
       "bad hex"},
      {"odd hex", {"telegram", "decode", "--telegram", "1", "--direction", "actual", "023"}, "odd number"},
      {"unknown signal",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"STW9":1})"},
       "unknown signal"},
      {"signal of other telegram",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"NSOLL_B":1})"},
       "not a signal of telegram 1"},
      {"signal of other direction",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"ZSW1":1})"},
       "not a signal of telegram 1"},
      {"out of range",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"STW1":65536})"},
       "out of range"},
      {"negative word",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"STW1":-1})"},
       "out of range"},
      {"bit field out of range",
       {"telegram", "encode", "--telegram", "2", "--direction", "setpoint", R"({"STW2":{"SignOfLife":16}})"},
       "out of range"},
      {"unknown bit",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"STW1":{"Foo":true}})"},
       "unknown bit"},
      {"speed without reference",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"NSOLL_A":{"speed":100}})"},
       "--reference-speed"},
      {"malformed JSON",
       {"telegram", "encode", "--telegram", "1", "--direction", "setpoint", R"({"STW1":)"},
       "JSON"},
      {"bad direction",
       {"telegram", "decode", "--telegram", "1", "--direction", "up", "0000"},
       "--direction"},
      {"missing telegram", {"telegram", "decode", "--direction", "actual", "0000"}, "--telegram"},
      {"bad byte order",
       {"telegram", "decode", "--telegram", "1", "--direction", "actual", "--byte-order", "x", "00000000"},
       "--byte-order"},
      {"bad nist offset",
       {"telegram", "decode", "--telegram", "83", "--direction", "actual", "--nist-b-offset", "6", "00"},
       "4, 8 or 12"},
      {"unknown command", {"frobnicate"}, "unknown command"},
      {"unknown action",
       {"telegram", "transmogrify", "--telegram", "1", "--direction", "actual"},
       "unknown action"},
  };
  for (const auto& c : cases) {
    const CliRun r = tomc(c.args);
    EXPECT_EQ(r.status, 2) << c.what;
    EXPECT_TRUE(r.out.empty()) << c.what << ": " << r.out;
    EXPECT_NE(r.err.find(c.message_part), std::string::npos) << c.what << ": " << r.err;
    ASSERT_FALSE(r.err.empty()) << c.what;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << c.what << ": not one line: " << r.err;
  }
}

}  // namespace
