/* SPDX-License-Identifier: MIT */
/*
 * oled_ssd0323.c: the SSD0323 OLED of the LM3S6965 EVB over SSI0
 * (oled_ssd0323.h).
 *
 * Wiring, as QEMU's lm3s6965evb has it (hw/arm/stellaris.c): SSI0 (an Arm
 * PL022) at 0x40008000 drives the controller; GPIO port C pin 7 is its
 * data/command line (low: command bytes, high: display data); port D
 * pin 0 selects the SD card on the same bus when low, so it is driven
 * high. On the board SSI0's own frame signal (PA3) selects the panel, and
 * PC6 switches on its 15 V supply; QEMU models neither, and both are set
 * as the board needs them.
 *
 * Every byte waits for its echo in the receive FIFO, so the bus is idle
 * whenever the data/command line changes. (QEMU's PL022 moves a byte at
 * once but stops when the receive FIFO is full, so the echoes must be read
 * in any case.)
 *
 * QEMU's model (hw/display/ssd0323.c) implements the window commands and
 * the horizontal address increment, and accepts but ignores the drive and
 * geometry set-up; it draws level L as the grey (L << 4) | L. The set-up
 * values below are the usual ones for a 128x64 panel on this controller,
 * not measured on glass.
 */
#include "oled_ssd0323.h"

#define REG(addr) (*(volatile uint32_t *)(addr))

/* System control: run-mode clock gating. */
#define SYSCTL_RCGC1 REG(0x400FE104u) /* bit 4: SSI0 */
#define SYSCTL_RCGC2 REG(0x400FE108u) /* bits 0, 2, 3: GPIO A, C, D */

/* GPIO ports (PL061). DATA is masked by address bits 9:2: writing to
 * base + (pins << 2) changes only those pins. */
#define GPIO_A 0x40004000u
#define GPIO_C 0x40006000u
#define GPIO_D 0x40007000u
#define GPIO_DATA(port, pins) REG((port) + ((uint32_t)(pins) << 2))
#define GPIO_DIR(port) REG((port) + 0x400u)
#define GPIO_AFSEL(port) REG((port) + 0x420u)
#define GPIO_DEN(port) REG((port) + 0x51Cu)

#define PIN_SSI0 0x2Cu  /* PA2 clock, PA3 frame, PA5 transmit */
#define PIN_DC 0x80u    /* PC7: 0 command, 1 data */
#define PIN_EN15V 0x40u /* PC6: the panel's 15 V supply */
#define PIN_SDCS 0x01u  /* PD0: the SD card's select, active low */

/* SSI0 (PL022). */
#define SSI0 0x40008000u
#define SSI_CR0 REG(SSI0 + 0x00u)
#define SSI_CR1 REG(SSI0 + 0x04u)
#define SSI_DR REG(SSI0 + 0x08u)
#define SSI_SR REG(SSI0 + 0x0Cu)
#define SSI_CPSR REG(SSI0 + 0x10u)
#define SSI_SR_TNF 0x02u /* transmit FIFO not full */
#define SSI_SR_RNE 0x04u /* receive FIFO not empty */
#define SSI_CR1_SSE 0x02u

/* SSD0323 commands (those QEMU's model knows). */
#define CMD_COLUMN 0x15u   /* start, end byte column (0..63) */
#define CMD_ROW 0x75u      /* start, end row (0..79) */
#define CMD_CONTRAST 0x81u
#define CMD_CURRENT_FULL 0x86u
#define CMD_REMAP 0xA0u    /* bit 2 clear: addresses advance along rows */
#define CMD_START_LINE 0xA1u
#define CMD_OFFSET 0xA2u
#define CMD_NORMAL 0xA4u
#define CMD_MUX 0xA8u
#define CMD_DCDC 0xADu
#define CMD_OFF 0xAEu
#define CMD_ON 0xAFu
#define CMD_PHASE 0xB1u
#define CMD_ROW_PERIOD 0xB2u
#define CMD_CLOCK 0xB3u
#define CMD_GREY_TABLE 0xB8u /* 8 bytes */
#define CMD_PRECHARGE 0xBCu
#define CMD_VCOMH 0xBEu
#define CMD_SEG_LOW 0xBFu

/* The controller has 80 rows of display memory; the panel shows 64. */
#define OLED_RAM_ROWS 80u

static const uint8_t oled_setup[] = {
    CMD_OFF,
    CMD_REMAP, 0x52,       /* nibble and COM remap, COM split */
    CMD_START_LINE, 0x00,
    CMD_OFFSET, 0x00,
    CMD_MUX, OLED_HEIGHT - 1,
    CMD_NORMAL,
    CMD_CONTRAST, 0x33,
    CMD_CURRENT_FULL,
    CMD_PHASE, 0x22,
    CMD_ROW_PERIOD, 0x23,
    CMD_CLOCK, 0x41,
    CMD_PRECHARGE, 0x10,
    CMD_VCOMH, 0x02,
    CMD_SEG_LOW, 0x0D,
    CMD_DCDC, 0x02,
    CMD_GREY_TABLE, 0x01, 0x11, 0x22, 0x32, 0x43, 0x54, 0x65, 0x76,
    CMD_ON,
};

static void ssi_send(uint8_t b)
{
    while (!(SSI_SR & SSI_SR_TNF))
        ;
    SSI_DR = b;
    while (!(SSI_SR & SSI_SR_RNE)) /* the echo: the byte is out */
        ;
    (void)SSI_DR;
}

static void oled_commands(const uint8_t *bytes, unsigned n)
{
    GPIO_DATA(GPIO_C, PIN_DC) = 0;
    while (n--)
        ssi_send(*bytes++);
}

void oled_data(const uint8_t *bytes, unsigned n)
{
    GPIO_DATA(GPIO_C, PIN_DC) = PIN_DC;
    while (n--)
        ssi_send(*bytes++);
}

void oled_window(unsigned c0, unsigned c1, unsigned r0, unsigned r1)
{
    const uint8_t cmd[6] = { CMD_COLUMN, (uint8_t)c0, (uint8_t)c1,
                             CMD_ROW, (uint8_t)r0, (uint8_t)r1 };
    oled_commands(cmd, sizeof cmd);
}

void oled_init(void)
{
    SYSCTL_RCGC1 |= 1u << 4;
    SYSCTL_RCGC2 |= (1u << 0) | (1u << 2) | (1u << 3);
    (void)SYSCTL_RCGC2; /* a few cycles before the ports answer */

    /* Levels first, then directions, so no pin glitches low. */
    GPIO_DATA(GPIO_D, PIN_SDCS) = PIN_SDCS;
    GPIO_DIR(GPIO_D) |= PIN_SDCS;
    GPIO_DEN(GPIO_D) |= PIN_SDCS;
    GPIO_DATA(GPIO_C, PIN_DC | PIN_EN15V) = PIN_EN15V;
    GPIO_DIR(GPIO_C) |= PIN_DC | PIN_EN15V;
    GPIO_DEN(GPIO_C) |= PIN_DC | PIN_EN15V;
    GPIO_AFSEL(GPIO_A) |= PIN_SSI0;
    GPIO_DEN(GPIO_A) |= PIN_SSI0;

    /* Master, SPI mode 3, 8-bit frames, clock = system clock / 2. */
    SSI_CR1 = 0;
    SSI_CPSR = 2;
    SSI_CR0 = (1u << 7) | (1u << 6) | 7u;
    SSI_CR1 = SSI_CR1_SSE;

    oled_commands(oled_setup, sizeof oled_setup);

    /* Black, all of the display memory (it holds noise at power-up). */
    static const uint8_t zeros[16];
    oled_window(0, OLED_WIDTH / 2 - 1, 0, OLED_RAM_ROWS - 1);
    for (unsigned i = 0; i < OLED_WIDTH / 2 * OLED_RAM_ROWS; i += sizeof zeros)
        oled_data(zeros, sizeof zeros);
}
