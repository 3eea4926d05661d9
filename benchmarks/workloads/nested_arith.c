/* C twin of nested_arith.st (gcc -O2). */
#include <stdint.h>
#include <stdio.h>

int main(void) {
    int32_t x = 7, y = 1, z = 0, h = 0;
    for (int32_t i = 1; i <= 4000000; ++i) {
        if (x % 2 == 0) x = x / 2;
        else x = 3 * x + 1;
        if (x > 1000000 || x == 1) x = i % 1000 + 7;
        y = (y * 31 + (x % 97) * 3 + 1) % 1000003;
        z = ((x + y) % 1000 * 2 + (i % 7) * (y % 11)) % 65536;
        h = (h + z * 3 - (z / 4) + 5) % 999983;
    }
    printf("%d\n", (h + y + x) % 1000003);
    return 0;
}
