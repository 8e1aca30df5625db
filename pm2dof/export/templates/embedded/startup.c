/* startup.c: the least a Cortex-M program under QEMU's MPS2 boards needs (no RTOS, no HAL).
 * Vector table, FPU on, .bss cleared, newlib's semihosting (rdimon) for printf, exit code to
 * QEMU. .data needs no copy: QEMU loads it straight into RAM (a real board's startup code,
 * from its vendor, copies it from flash). */
#include <stdint.h>
#include <stdlib.h>

extern uint32_t __stack_top, __bss_start__, __bss_end__;
extern int main(void);
extern void initialise_monitor_handles(void);

void _init(void) {}
void _fini(void) {}

static void hang(void)
{
    for (;;) {
    }
}

void Reset_Handler(void)
{
    uint32_t *p;
    *(volatile uint32_t *)0xE000ED88 |= 0xFu << 20; /* CPACR: CP10, CP11 full access (FPU) */
    __asm volatile("dsb\n\tisb");
    for (p = &__bss_start__; p < &__bss_end__; p++)
        *p = 0;
    initialise_monitor_handles();
    exit(main());
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(uintptr_t)&__stack_top, Reset_Handler, hang, hang, hang, hang, hang,
    0, 0, 0, 0, hang, hang, 0, hang, hang};
