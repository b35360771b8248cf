// affinterp: the suite's command-line interface. Each command is in its own file (cmd_*.cpp).
#include "experiments/apps/cli/command.hpp"
#include "experiments/support/interrupt_cleanup.hpp"

#include <malloc.h>

#include <iostream>

int main(int argc, char** argv) {
  using namespace affinterp::cli;
  affinterp::remove_registered_paths_on_interrupt();  // an interrupted run leaves no staging folder
  // A frame of a 1M-triangle mesh and its right-hand sides are 8 MB arrays. Under glibc's defaults the solver threads
  // get each one from a fresh mmap whose pages the kernel zeroes, and the writer's free returns it: a sizeable
  // part of a frame at 1M triangles (bench_cli_scale measures it, with and without these two settings). Kept in the
  // heap, freed arrays are reused; what a run keeps is its peak, as before.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  CLI::App app{
      "affinterp: decide the claims of Kaji et al. (SCA 2012) and Matsushita (thesis 2015) on rigid 2D "
      "shape interpolation with affine maps, and run their algorithms.",
      "affinterp"};
  app.set_version_flag("--version", std::string("affinterp ") + AFFINTERP_VERSION);
  app.require_subcommand(1);
  add_claims_command(app);
  add_report_command(app);
  add_exp3_command(app);
  add_eig3_command(app);
  add_shapes_command(app);
  add_interpolate_command(app);
  add_view_command(app);
  add_decide_command(app);
  add_bench_command(app);
  add_prove_command(app);
  add_pair_command(app);
  add_blend_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "affinterp: " << e.what() << " (see --help)\n";
    return usage_error;
  } catch (const CommandFailed& e) {
    std::cerr << "affinterp: " << e.what() << "\n";
    return e.status;
  } catch (const std::exception& e) {
    std::cerr << "affinterp: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
