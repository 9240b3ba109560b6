# Read by ctest after the tests gtest_discover_tests found (tests/CMakeLists.txt): a test that
# times itself against a quiet run of its own runs alone (at ctest -j4 other tests would run
# beside one of its phases and not the other). gtest_discover_tests names a DISABLED_ test
# without the prefix (and marks it disabled).
set_tests_properties("Starvation.AFloodOfNeverEndingRequestsDoesNotStarveAnotherClient"
    "Starvation.AFloodFromFortyNamesOnAnUnkeyedBusDoesNotStarveAnotherClient"
    PROPERTIES RUN_SERIAL TRUE)
