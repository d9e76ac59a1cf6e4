#pragma once
// The files the page loads besides itself, embedded at build time (diagnostics/CMakeLists.txt,
// embed_file.cmake): the plotting library uPlot (npm, diagnostics/web/package.json), served by the server
// itself so that the page needs no network beyond the PLC (decision D7).
#include <string_view>

#include "tomc/diagnostics/server.hpp"  // web_page()

namespace tomc::diagnostics {

std::string_view uplot_script() noexcept;  // uPlot.iife.min.js
std::string_view uplot_style() noexcept;   // uPlot.min.css

}  // namespace tomc::diagnostics
