# Fixture design (bench/design_bench.cpp): placements per second on the ratchet pawl and the distribution model.
add_executable(design_bench design_bench.cpp)
target_link_libraries(design_bench PRIVATE contactcert_solvers contactcert_geometry contactcert_exact contactcert_runtime
                      benchmark::benchmark)
