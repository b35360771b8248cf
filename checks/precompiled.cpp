// The translation unit that builds the test programs' shared precompiled header (checks/CMakeLists.txt,
// affinterp_check_pch); it has no code of its own.
