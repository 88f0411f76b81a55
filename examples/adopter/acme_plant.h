/* The ACME X1's motor and load, reduced to what its HAL needs to be
 * believable on a host: a shaft that follows its commands within the
 * velocity limit, and a power stage that warms up unless the fan cools it.
 * Plain C, no heap. */
#ifndef ACME_PLANT_H
#define ACME_PLANT_H

#include <stdbool.h>

typedef enum acme_plant_mode {
    ACME_PLANT_HOLD,     /* hold pos_deg */
    ACME_PLANT_POSITION, /* travel to target_deg at up to vel_limit_rpm, then hold */
    ACME_PLANT_VELOCITY, /* turn at target_rpm (within the limit) */
    ACME_PLANT_TORQUE    /* free-wheel: the model has no load, the shaft keeps its speed */
} acme_plant_mode_t;

typedef struct acme_plant {
    acme_plant_mode_t mode;
    float pos_deg;        /* output shaft */
    float vel_rpm;
    float target_deg;
    float target_rpm;
    float vel_limit_rpm;  /* > 0 */
    float fan_duty;       /* 0..1 */
    float stage_temp_c;   /* power stage temperature */
} acme_plant_t;

/* At rest at 0 deg, 25 degC, fan off. */
void acme_plant_init(acme_plant_t *plant, float vel_limit_rpm);

/* Advance the model by @p dt_s seconds. */
void acme_plant_step(acme_plant_t *plant, float dt_s);

/* True when a position move has arrived (or no position move runs). */
bool acme_plant_arrived(const acme_plant_t *plant);

#endif /* ACME_PLANT_H */
