/* The smallest complete use of the bearing library: build the hub-motor bearing in static
   storage, settle it, take ten real-time steps and print the force, then the friction of the
   last step. */
#include <stdio.h>

#include "bearing.h"

static _Alignas(BEARING_STORAGE_ALIGN) unsigned char storage[BEARING_STORAGE_SIZE];

int main(void) {
  BearingConfig config;
  BearingHandle *bearing = NULL;
  BearingRefusal refusal = {0};
  BearingStatus status = bearing_preset(BEARING_PRESET_HUB_MOTOR, &config);
  if (status == BEARING_STATUS_OK) {
    config.film = BEARING_FILM_INT; /* the preset's choice already; any BearingFilm value */
    status = bearing_init(storage, sizeof storage, &config, &bearing, &refusal);
  }
  if (status != BEARING_STATUS_OK) {
    fprintf(stderr, "bearing_init: %s %s\n", bearing_error_message(status), refusal.field);
    return 1;
  }

  /* The inner race 5 um below the centre, the shaft at 2000 rad/s, stepped at 10 kHz. */
  BearingState state = {.displacement_m = {0.0f, -5.0e-6f}, .shaft_speed_rad_s = 2000.0f};
  BearingOutput out;
  status = bearing_settle(bearing, &state, 6, &out);
  for (int step = 0; step < 10 && status == BEARING_STATUS_OK; ++step) {
    status = bearing_advance(bearing, &state, 1.0e-4f, &out);
  }
  if (status != BEARING_STATUS_OK) {
    bearing_last_refusal(bearing, &refusal);
    fprintf(stderr, "step: %s %s\n", bearing_error_message(status), refusal.field);
    return 1;
  }
  printf("F = %.9g %.9g N, k_yy = %.9g N/m, cage at %.9g rad\n", out.force_n[0], out.force_n[1],
         out.stiffness[1][1], out.cage_angle_rad);

  /* The friction of that step (a separate call, at the rate the friction is wanted). */
  status = bearing_friction(bearing, state.shaft_speed_rad_s, &out);
  if (status != BEARING_STATUS_OK) {
    fprintf(stderr, "bearing_friction: %s\n", bearing_error_message(status));
    return 1;
  }
  printf("friction torque %.9g N m, power loss %.9g W = %.9g rolling + %.9g viscous + %.9g boundary\n",
         out.friction_torque_nm, out.power_loss_w, out.power_loss_split_w[0], out.power_loss_split_w[1],
         out.power_loss_split_w[2]);
  printf("first roller (at the cage angle): lambda %.9g inner, %.9g outer\n", out.rollers[0].lambda_in, out.rollers[0].lambda_out);
  return 0;
}
