#pragma once
// Running the `shadowlab` executable from a test: exit code, stdout and stderr.
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <gtest/gtest.h>

namespace shadowlab::testing {

struct CliResult {
    int exit_code;
    std::string out, err;
};

inline std::string slurp(const std::string& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// SHADOWLAB_CLI is the executable's path, defined by the test target.
inline CliResult run_cli(const std::string& args) {
    // One file per process: ctest runs the CLI tests in parallel.
    const std::string err_file = ::testing::TempDir() + "shadowlab_cli_stderr_" + std::to_string(getpid()) + ".txt";
    const std::string command = std::string(SHADOWLAB_CLI) + " " + args + " 2>" + err_file;
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    std::array<char, 4096> buffer;
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
    const int status = pclose(pipe);
    return {WEXITSTATUS(status), out, slurp(err_file)};
}

}  // namespace shadowlab::testing
