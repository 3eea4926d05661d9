/* C twin of string_build.st (gcc -O2): a STRING[255] as a char array with
   its length, appends as a compiler from ST would emit them. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static size_t append(char* s, size_t len, const char* piece) {
    size_t n = strlen(piece);
    if (len + n > 255) n = 255 - len;
    memcpy(s + len, piece, n);
    s[len + n] = 0;
    return len + n;
}

int main(void) {
    char s[256], num[16];
    int32_t checksum = 0, matches = 0;
    for (int32_t i = 1; i <= 50000; ++i) {
        size_t len = append(s, 0, "n");
        for (int32_t j = 1; j <= 25; ++j) {
            snprintf(num, sizeof num, "%d", (i + j * 7) % 97);
            len = append(s, len, num);
            if (j % 5 == 0) len = append(s, len, ",");
        }
        if (strncmp(s, "n1", 2) == 0 && len >= 2) matches = matches + 1;
        checksum = (checksum * 7 + (int32_t)strlen(s)) % 1000003;
    }
    printf("%d\n", checksum + matches);
    return 0;
}
