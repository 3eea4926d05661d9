/* C twin of many_args.st (gcc -O2), as a compiler from ST would emit it:
   one C function per ST FUNCTION, not inlined by hand. */
#include <stdint.h>
#include <stdio.h>

static int32_t blend5(int32_t a, int32_t b, int32_t c, int32_t d, int32_t e) {
    return (a * 7 + b * 3 + c + d * 2 + e) % 65521;
}

static int32_t max3(int32_t a, int32_t b, int32_t c) {
    int32_t m = a;
    if (b > m) m = b;
    if (c > m) m = c;
    return m;
}

static int in_band(int32_t v, int32_t lo, int32_t hi) { return v >= lo && v <= hi; }

int main(void) {
    int32_t checksum = 0, hits = 0, k = 17;
    for (int32_t i = 1; i <= 2000000; ++i) {
        checksum = blend5(checksum, i % 1000, i % 13, max3(i % 100, 50, k), 4);
        if (in_band(checksum, 1000, 40000)) hits = hits + 1;
        k = (k + 7) % 90;
    }
    printf("%d\n", checksum + hits);
    return 0;
}
