// SPDX-License-Identifier: GPL-3.0-or-later
// Default options of AddressSanitizer, UndefinedBehaviorSanitizer and
// LeakSanitizer for every executable of a sanitizer build (the asan preset;
// cmake/VVWarnings.cmake adds this file to each executable target there and
// nowhere else). Built in rather than set by ctest so that they hold for the
// unit tests, for the test discovery run at build time, for the CLI processes
// the tests start, and for a developer running a program by hand. The
// ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS environment variables are read
// after these and override them.
//
// LeakSanitizer reads tests/sanitizers/lsan.supp (VV_LSAN_SUPPRESSIONS, an
// absolute path): third-party libraries only, never our code.

extern "C" {

// The runtimes look these up by name; they must have C linkage and be visible.
__attribute__((visibility("default"), used)) const char* __asan_default_options();
__attribute__((visibility("default"), used)) const char* __ubsan_default_options();
__attribute__((visibility("default"), used)) const char* __lsan_default_options();

const char* __asan_default_options() {
    // halt at the first error (the default for ASan, stated for clarity);
    // leaks are checked at exit (LeakSanitizer, default on x86-64 Linux).
    return "halt_on_error=1:detect_leaks=1:check_initialization_order=1:"
           "strict_init_order=1:detect_invalid_pointer_pairs=0";
}

const char* __ubsan_default_options() {
    // -fno-sanitize-recover=undefined (asan preset) already makes every UBSan
    // report fatal; the stack shows where.
    return "halt_on_error=1:print_stacktrace=1";
}

const char* __lsan_default_options() {
    return "suppressions=" VV_LSAN_SUPPRESSIONS ":print_suppressions=0";
}

// Shared libraries are never unloaded in sanitizer builds. LeakSanitizer
// checks at exit and names each stack frame's module then; a library that was
// dlclose()d before (Mesa's DRI driver, unloaded with the last GL context)
// shows up as "<unknown module>" or under a wrong name, so its suppression
// cannot match. This definition in the executable takes the place of libc's
// for every library (libGLX / libglvnd, Qt's plugin loader): the call
// succeeds and the library stays mapped until exit.
__attribute__((visibility("default"), used)) int dlclose(void* handle);
int dlclose(void* handle) {
    static_cast<void>(handle);
    return 0;
}

}  // extern "C"
