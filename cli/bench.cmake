# `contactcert bench`: included from cli/CMakeLists.txt. The families library (cli/bench/) is built with the CLI
# whatever CONTACTCERT_BENCH says, since the command is part of the product.
add_subdirectory(bench)
target_sources(contactcert_cli PRIVATE bench.cpp bench_report.cpp bench_aggregate.cpp bench_tables.cpp bench_plot.cpp
                                         bench_json.cpp)
target_link_libraries(contactcert_cli PRIVATE contactcert_bench_families)
