// The symmesh subcommands. The CLI is thin: it parses, calls the library, prints.
#pragma once
#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace symmesh::apps {

/// Exit codes shared by all commands.
enum Exit : int { ok = 0, negative = 1, bad_input = 2 };

void add_check(CLI::App& app, int& exit_code);
void add_graph(CLI::App& app, int& exit_code);
void add_lemmas(CLI::App& app, int& exit_code);
void add_bpp(CLI::App& app, int& exit_code);
void add_generate(CLI::App& app, int& exit_code);
void add_example(CLI::App& app, int& exit_code);
void add_cut(CLI::App& app, int& exit_code);
void add_solve(CLI::App& app, int& exit_code);
void add_render(CLI::App& app, int& exit_code);
void add_adapt(CLI::App& app, int& exit_code);

/// Peak resident set size of this process, in bytes (the reports' peak_rss_bytes).
std::size_t peak_rss_bytes();

/// Prints "symmesh: error: <message>" as one line on stderr.
void print_error(const std::string& message);

} // namespace symmesh::apps
