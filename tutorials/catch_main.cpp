// Catch2's main for every tutorial check, compiled once (it takes a while).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
