# What a fresh build costs the compiler (issue 28, decision 0348): the small
# files of each library compiled in batches (unity builds), and the code that
# never runs in a scan compiled with less optimisation. Included from the top
# CMakeLists.txt once the libraries exist; benchmarks/README.md "Build time"
# has the measurements.

# ---- unity builds: the files of a library compiled STRUN_UNITY_BATCH at a
# time, one compiler run per batch. The files of a batch share the parsing of
# their headers and the instantiation and code generation of the inline and
# template code they all use (the AST and program-model destructors, fmt,
# nlohmann/json, CLI11). Every file still compiles on its own
# (-DSTRUN_UNITY=OFF); file-local helpers have names of their own so that
# they do not clash inside a batch.
option(STRUN_UNITY "compile the files of each strun library in batches (unity builds)" ON)
set(STRUN_UNITY_BATCH 16 CACHE STRING "files per unity batch of the strun libraries")
set(STRUN_TEST_UNITY_BATCH 8 CACHE STRING "files per unity batch of the unit tests")
if(STRUN_UNITY)
  # 16 rather than 8 (decision 0491): fewer copies of the same inline and
  # template code; the largest batch stays under 700 MB of compiler memory.
  set_target_properties(strun_stdlib strun_ast strun_source_readers strun_runtime strun_interp strun_live strun_live_network
    PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${STRUN_UNITY_BATCH})
  # All of CLI11's users in one batch: CLI11 2.1 (Debian's) is header-only,
  # and each batch that includes it compiles its parser, validators and
  # formatters again (about 8 s at -O2). The editor protocols and the other
  # commands in batches of 8: in one batch of 16 the compiler needed 900 MB.
  set_target_properties(strun_cli PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
  set_target_properties(strun_commands PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  # Template-heavy files that share little with their neighbours: alone, so
  # that the two cores share them and no batch is much longer than the others.
  # And the evaluator's own files (interpreter/exec) and the checker's files
  # that build call nodes: in a batch, GCC's inlining limits for the larger
  # unit made it call the statement loop of the callee's body out of line in
  # CallFbStmtOf and CallPou::runFramed (both defined once, in call_nodes.cpp,
  # which is compiled alone): fb_io +5.3 %, fb_methods +6.2 %, many_args +3.1 %
  # instructions.
  file(GLOB EXEC_SOURCES ${CMAKE_SOURCE_DIR}/interpreter/exec/*.cpp)
  set_source_files_properties(${EXEC_SOURCES}
    ${CMAKE_SOURCE_DIR}/interpreter/sema/checker_call.cpp ${CMAKE_SOURCE_DIR}/interpreter/sema/checker_oop.cpp
    ${CMAKE_SOURCE_DIR}/interpreter/sema/checker_stmt.cpp ${CMAKE_SOURCE_DIR}/interpreter/sema/checker_inline.cpp
    ${CMAKE_SOURCE_DIR}/interpreter/sema/fuse.cpp
    ${CMAKE_SOURCE_DIR}/interpreter/sema/fuse_binary_dint.cpp ${CMAKE_SOURCE_DIR}/interpreter/sema/fuse_binary_lint.cpp
    ${CMAKE_SOURCE_DIR}/interpreter/sema/fuse_binary_real.cpp ${CMAKE_SOURCE_DIR}/interpreter/sema/fuse_binary_lreal.cpp
    ${CMAKE_SOURCE_DIR}/stdlib/fmt_library.cpp
    PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endif()

# ---- cold code at -O1 instead of the Release build type's -O3: the command
# line and the editor protocols (LSP, DAP), which run once per command or
# per request, the network side of the live layer (HTTP, Modbus), which
# runs on threads of its own, and the readers of project formats
# (interpreter/source: PLCopen XML, TwinCAT, Beremiz, SFC, IL), which run
# once per compile of such a project. Never the evaluator
# (interpreter/exec), the checker, the runtime scheduler, the control plane
# (its hooks run at every activation of a live run), the ST scanner and AST
# builder (`check` of 30 000 lines: +2.8 % instructions with them at -O1)
# or anything else a scan or `check` runs. -O1 compiles these files in
# about half the time of -O2 (decision 0491). What made -O1 cost at every
# start before (decision 0348), the process image's per-byte construct and
# destroy loops inlined here at -O1, is now compiled out of line in the
# runtime (runtime/zeroed_pages.cpp).
set(STRUN_COLD_OPT "-O1" CACHE STRING "optimisation of the command line, editor, network and project-reader code (empty: as the build type)")
if(STRUN_COLD_OPT AND CMAKE_BUILD_TYPE STREQUAL "Release")
  target_compile_options(strun_cli PRIVATE ${STRUN_COLD_OPT})
  target_compile_options(strun_commands PRIVATE ${STRUN_COLD_OPT})
  target_compile_options(strun_source_readers PRIVATE ${STRUN_COLD_OPT})
  target_compile_options(strun_live_network PRIVATE ${STRUN_COLD_OPT})
  # The build-time tool that embeds the standard library's ST sources.
  target_compile_options(strun_embed_library PRIVATE ${STRUN_COLD_OPT})
endif()

# ---- -O2 instead of -O3 for strun_ast (decision 0470): the ST scanner and
# the AST builder, which run once per compile and hold no evaluator code.
# -O3's extra inlining and loop transformations cost a fifth more compile
# time there (the source readers' batch: 25.3 s at -O3, 20.1 s at -O2). Not
# the other libraries: the evaluator's node templates are instantiated
# wherever the checker, the built-ins and the library bindings build nodes,
# and at -O2 in those files GCC stopped inlining the statement loop into
# CASE arms (state_machine +1.3 % instructions), SwapElems (bubble_sort
# +1.8 %) and the string edit nodes (string_build +0.5 %).
set(STRUN_AST_OPT "-O2" CACHE STRING "optimisation of strun_ast (empty: as the build type)")
if(STRUN_AST_OPT AND CMAKE_BUILD_TYPE STREQUAL "Release")
  target_compile_options(strun_ast PRIVATE ${STRUN_AST_OPT})
endif()

# ---- the generated parser (grammar/*.g4 -> STParser.cpp): GCC's -O1 instead
# of the build type's -O3 saves a third of its compile time; the parser's
# work is ANTLR's runtime (a Debian library, compiled as Debian compiles it)
# more than the generated rule functions (benchmarks/README.md: `check` of
# 30 000 lines).
set(STRUN_PARSER_OPT "-O1" CACHE STRING "optimisation of the generated parser (empty: as the build type)")
if(STRUN_PARSER_OPT AND CMAKE_BUILD_TYPE STREQUAL "Release")
  target_compile_options(strun_grammar PRIVATE ${STRUN_PARSER_OPT})
  # Except the program's operator new and delete (decision 0499): every
  # allocation runs them, and at -O1 they call malloc and free instead of jumping there.
  set_source_files_properties(${GRAMMAR_DIR}/atn_heap.cpp PROPERTIES COMPILE_OPTIONS -O2)
endif()

# ---- the test executables' own files (tests/): the code they run is the
# libraries', built as above; their own is assertions and setup, run once.
# Compiled at -O0 (decision 0491; -O1 before, decision 0348) and (unit tests)
# in unity batches, since most of their compile time is parsing the same
# headers again in each file and generating Catch2's assertion code: a batch
# of eight interpreter tests took 21.1 s at -O1 and 12.9 s at -O0.
set(STRUN_TEST_OPT "-O0" CACHE STRING "optimisation of the test executables' own files (empty: as the build type)")
# The test drivers that are not unit tests (the conformance and hostile-input
# checkers, the control plane's and the Modbus map's tests, ...): only the
# optimisation. Not the benchmarks' executables or the Modbus load generator,
# whose own speed is measured.
function(strun_test_driver_opt target)
  if(STRUN_TEST_OPT AND CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${target} PRIVATE ${STRUN_TEST_OPT})
  endif()
endfunction()
# The unit tests: the optimisation and unity batches.
function(strun_test_build_cost target)
  strun_test_driver_opt(${target})
  if(STRUN_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${STRUN_TEST_UNITY_BATCH})
  endif()
endfunction()

# ---- the libraries compile side by side: with the Makefile generator a
# static library's files wait until every library it links is built, which
# made the build a chain (grammar -> ast -> interp -> live -> the
# executable's files) with one core idle at the tail of each link. A static
# library needs the others' headers, not their archives: with
# OPTIMIZE_DEPENDENCIES it waits only for the libraries that generate
# sources (strun_grammar: the parser's headers; strun_stdlib, strun_live:
# embedded files), so strun_ast, strun_runtime, strun_interp and strun_live
# start together once the parser is generated (decision 0469).
set_target_properties(strun_stdlib strun_ast strun_source_readers strun_runtime strun_interp strun_live strun_live_network
  PROPERTIES OPTIMIZE_DEPENDENCIES ON)
