# The plant's sources, one list for src/plant/CMakeLists.txt and the fuzz build (fuzz/CMakeLists.txt),
# which compiles them instrumented.
set(BONL_PLANT_SOURCES parameters.cpp integrator.cpp simulator.cpp stepping_plant.cpp excitation.cpp)
