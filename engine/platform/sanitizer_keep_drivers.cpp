// Sanitizer builds only (TERRASOL_SANITIZE): every executable that can load a GL driver gets this
// dlclose, which keeps libraries mapped. Mesa unloads its driver in eglTerminate and at exit, and
// LeakSanitizer cannot name frames in an unloaded library, so its once-per-process allocations could
// not be told apart from ours and suppressed (tests/lsan.supp). Never part of a normal build.

extern "C" int dlclose(void*) {
  return 0;
}
