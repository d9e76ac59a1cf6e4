#pragma once
// Internal: the part of the dds_gateway adapter's loading that config.cpp's load_drive() calls.
#include "json_reader.hpp"

namespace tomc::scenario::detail {

// With the dds_gateway adapter: every key of `drive` besides adapter, telegram and supplementary_telegram is
// a simulated-drive parameter, which belongs to the gateway's configuration; each is reported.
void reject_simulated_drive_keys(const Json& drive, ObjectReader& reader, Problems& problems);

}  // namespace tomc::scenario::detail
