# What keeps a build short on 2 cores (docs/results/build.md has the measurements).
#
# - Unity builds: a target's files are compiled in batches of ENVDESIGN_UNITY_BATCH, one
#   compiler run a batch. Every file here includes ~75,000 lines of C++20 standard library
#   (often nlohmann/json, spdlog, CLI11 and the LCM types too) and instantiates the same
#   templates; a batch parses, instantiates and optimises them once. The libraries, services
#   and clients: half the CPU time; the tests too (tests/CMakeLists.txt).
#   A file whose file-local names collide with another's fails to compile in its batch:
#   rename the name, move a helper several files share into a header of their folder, or
#   set SKIP_UNITY_BUILD_INCLUSION on the file. -DENVDESIGN_UNITY_BUILD=OFF builds file by
#   file.
# - ccache, when installed, is the compiler launcher: a clean rebuild or a second build
#   folder compiles only what it has not seen. A launcher given to CMake wins.
option(ENVDESIGN_UNITY_BUILD "Compile each target's files in batches (unity builds)" ON)
set(ENVDESIGN_UNITY_BATCH 8 CACHE STRING "Files a unity batch holds")
if(ENVDESIGN_UNITY_BUILD)
    set(CMAKE_UNITY_BUILD ON)
    set(CMAKE_UNITY_BUILD_BATCH_SIZE ${ENVDESIGN_UNITY_BATCH})
endif()

find_program(ENVDESIGN_CCACHE ccache)
mark_as_advanced(ENVDESIGN_CCACHE)
if(ENVDESIGN_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
    set(CMAKE_C_COMPILER_LAUNCHER ${ENVDESIGN_CCACHE})
    set(CMAKE_CXX_COMPILER_LAUNCHER ${ENVDESIGN_CCACHE})
endif()
