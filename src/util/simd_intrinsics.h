#pragma once
// <immintrin.h>, included so that its inlined AVX-512 bodies are not reported against our code:
// GCC 12 warns -Wmaybe-uninitialized on the `__Y` of `_mm512_undefined_*` inside avx512fintrin.h
// wherever Eigen's or our packet code inlines it, a false positive in the compiler's own header.
// Diagnostic pragmas cover the locations between push and pop, so the header's lines are silenced
// and the project's are not. Include this, never <immintrin.h> directly.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
