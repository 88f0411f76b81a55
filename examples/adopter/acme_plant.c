/* The ACME X1's plant model (acme_plant.h). */
#include "acme_plant.h"

#define DEG_PER_S_PER_RPM 6.0f /* 1 r/min = 360 deg / 60 s */
#define AMBIENT_C 25.0f

void acme_plant_init(acme_plant_t *plant, float vel_limit_rpm)
{
    *plant = (acme_plant_t){0};
    plant->mode = ACME_PLANT_HOLD;
    plant->vel_limit_rpm = vel_limit_rpm;
    plant->stage_temp_c = AMBIENT_C;
}

static float clamp(float value, float limit)
{
    return value > limit ? limit : (value < -limit ? -limit : value);
}

void acme_plant_step(acme_plant_t *plant, float dt_s)
{
    switch (plant->mode) {
    case ACME_PLANT_POSITION: {
        float to_go = plant->target_deg - plant->pos_deg;
        float step = plant->vel_limit_rpm * DEG_PER_S_PER_RPM * dt_s;
        if (to_go <= step && to_go >= -step) {
            plant->pos_deg = plant->target_deg;
            plant->vel_rpm = 0.0f;
            plant->mode = ACME_PLANT_HOLD;
        } else {
            plant->vel_rpm = to_go > 0.0f ? plant->vel_limit_rpm : -plant->vel_limit_rpm;
            plant->pos_deg += to_go > 0.0f ? step : -step;
        }
        break;
    }
    case ACME_PLANT_VELOCITY:
        plant->vel_rpm = clamp(plant->target_rpm, plant->vel_limit_rpm);
        plant->pos_deg += plant->vel_rpm * DEG_PER_S_PER_RPM * dt_s;
        break;
    case ACME_PLANT_TORQUE:
        plant->pos_deg += plant->vel_rpm * DEG_PER_S_PER_RPM * dt_s;
        break;
    case ACME_PLANT_HOLD:
    default:
        plant->vel_rpm = 0.0f;
        break;
    }
    /* the stage heats with speed and cools towards ambient, faster with the fan */
    float heating = 0.002f * (plant->vel_rpm < 0.0f ? -plant->vel_rpm : plant->vel_rpm);
    float cooling = (0.05f + 0.5f * plant->fan_duty) * (plant->stage_temp_c - AMBIENT_C);
    plant->stage_temp_c += (heating - cooling) * dt_s;
}

bool acme_plant_arrived(const acme_plant_t *plant)
{
    return plant->mode != ACME_PLANT_POSITION;
}
