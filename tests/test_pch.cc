// Copyright contactlaws authors.
//
// The source that tests/CMakeLists.txt's contactlaws_test_pch_* targets
// compile to make GoogleTest's precompiled header, which every test reuses.
