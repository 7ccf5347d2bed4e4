/* Linked into the fuzz harness (scripts/fuzz_primitives.sh): before main, sets the x87
 * precision control from X87_PC (24, 53 or 64 bits) and the rounding mode from ROUND
 * (zero, up, down), to see what the primitives do where a program changed them. */
#include <fenv.h>
#include <stdlib.h>

__attribute__((constructor)) static void fuzz_environment(void) {
    const char *pc = getenv("X87_PC"), *round = getenv("ROUND");
    if (pc) {
        int bits = atoi(pc);
        unsigned short cw;
        __asm__ volatile("fnstcw %0" : "=m"(cw));
        cw &= ~0x300;
        if (bits == 53) cw |= 0x200;
        else if (bits == 64) cw |= 0x300;
        __asm__ volatile("fldcw %0" : : "m"(cw));
    }
    if (round && round[0] == 'z') fesetround(FE_TOWARDZERO);
    if (round && round[0] == 'u') fesetround(FE_UPWARD);
    if (round && round[0] == 'd') fesetround(FE_DOWNWARD);
}
