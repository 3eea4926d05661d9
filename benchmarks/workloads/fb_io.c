/* C twin of fb_io.st (gcc -O2): a function block as a struct and a body
   function taking its address, as a compiler from ST would emit it. */
#include <stdint.h>
#include <stdio.h>

typedef struct {
    int32_t x, w;
    uint8_t enable;
    int32_t total, count;
    uint8_t high;
} Accumulator;

static void accumulator_body(Accumulator* fb) {
    if (fb->enable) {
        fb->total = (fb->total + fb->x * fb->w) % 1000003;
        fb->count = fb->count + 1;
    }
    fb->high = fb->total > 500000;
}

int main(void) {
    Accumulator first = {0}, second = {0};
    int32_t highs = 0, t = 0;
    for (int32_t i = 1; i <= 2000000; ++i) {
        first.x = i % 100;
        first.w = 3;
        first.enable = i % 3 != 0;
        accumulator_body(&first);
        second.x = first.total % 1000;
        second.w = 2;
        second.enable = first.high;
        accumulator_body(&second);
        t = second.total;
        if (second.high) highs = highs + 1;
    }
    printf("%d\n", (highs + t + first.total + first.count + second.count) % 1000003);
    return 0;
}
