// symmesh — symmetry- and similarity-aware volumetric meshing, command-line tool.
#include "symmesh/apps/commands.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"symmesh: symmetry- and similarity-aware volumetric meshing with templated "
               "structures (exact core)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "symmesh 0.1.0");
  int exit_code = symmesh::apps::ok;
  symmesh::apps::add_check(app, exit_code);
  symmesh::apps::add_graph(app, exit_code);
  symmesh::apps::add_lemmas(app, exit_code);
  symmesh::apps::add_bpp(app, exit_code);
  symmesh::apps::add_generate(app, exit_code);
  symmesh::apps::add_example(app, exit_code);
  symmesh::apps::add_cut(app, exit_code);
  symmesh::apps::add_solve(app, exit_code);
  symmesh::apps::add_render(app, exit_code);
  symmesh::apps::add_adapt(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    if (what.empty()) what = e.get_name();
    symmesh::apps::print_error(what + " (see symmesh --help)");
    return symmesh::apps::bad_input;
  } catch (const std::exception& e) {
    symmesh::apps::print_error(e.what());
    return symmesh::apps::bad_input;
  }
  return exit_code;
}
