// SPDX-License-Identifier: BSD-3-Clause
// shadinglab: the command-line front end. One subcommand per job.
#include "Commands.h"

#include "shadinglab/Version.h"

#include <cstring>
#include <exception>
#include <iostream>

namespace
{

const char* kUsage = "usage: shadinglab COMMAND [options]   (shadinglab COMMAND --help)\n"
                     "       shadinglab --version\n"
                     "commands:\n"
                     "  brdf      tabulate a reflectance model or one of its terms as CSV\n"
                     "  render    render a mesh in one shading mode to PNG\n"
                     "  compare   render a mesh in every shading mode, side by side\n"
                     "  normals   repair, subdivide and compute vertex normals of a mesh\n"
                     "  accuracy  frame time against error for every mode, vs exact surfaces\n"
                     "  settings  every setting (flags, ParaView properties) as Markdown\n";

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))
  {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version"))
  {
    std::cout << "shadinglab " << SHADINGLAB_VERSION << "\n";
    return 0;
  }
  const std::string command = argv[1];
  try
  {
    if (command == "brdf")
    {
      return shadinglab::cli::RunBrdf(argc - 2, argv + 2);
    }
    if (command == "normals")
    {
      return shadinglab::cli::RunNormals(argc - 2, argv + 2);
    }
    if (command == "compare")
    {
      return shadinglab::cli::RunCompare(argc - 2, argv + 2);
    }
    if (command == "accuracy")
    {
      return shadinglab::cli::RunAccuracy(argc - 2, argv + 2);
    }
    if (command == "settings")
    {
      return shadinglab::cli::RunSettings(argc - 2, argv + 2);
    }
    if (command == "render")
    {
      return shadinglab::cli::RunRender(argc - 2, argv + 2);
    }
    std::cerr << "shadinglab: error: unknown command '" << command
              << "' (see shadinglab --help)\n";
    return 2;
  }
  catch (const shadinglab::cli::UsageError& e)
  {
    std::cerr << "shadinglab " << command << ": error: " << e.what() << "\n";
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "shadinglab " << command << ": error: " << e.what() << "\n";
    return 1;
  }
}
