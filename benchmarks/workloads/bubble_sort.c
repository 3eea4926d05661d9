/* C twin of bubble_sort.st (gcc -O2). */
#include <stdint.h>
#include <stdio.h>

int main(void) {
    int32_t a[401];
    int32_t seed = 4242, checksum = 0;
    for (int rep = 1; rep <= 150; ++rep) {
        for (int k = 1; k <= 400; ++k) {
            seed = 16807 * (seed % 127773) - 2836 * (seed / 127773);
            if (seed <= 0) seed = seed + 2147483647;
            a[k] = seed % 100000;
        }
        int32_t n = 399;
        int swapped = 1;
        while (swapped) {
            swapped = 0;
            for (int32_t j = 1; j <= n; ++j) {
                if (a[j] > a[j + 1]) {
                    int32_t t = a[j];
                    a[j] = a[j + 1];
                    a[j + 1] = t;
                    swapped = 1;
                }
            }
            n = n - 1;
        }
        for (int k = 1; k <= 400; ++k) checksum = (checksum * 31 + a[k] % 1000) % 1000003;
    }
    printf("%d\n", checksum);
    return 0;
}
