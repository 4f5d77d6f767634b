#pragma once
// Capture radius r_c of a collision of grinding media through a layer of particles of size x:
// the radius, around the line of centres, inside which the gap between the media surfaces is at
// most x when the media touch (the particles there are nipped). Pure geometry of spheres, this
// code's own assumption: the published UFRJ capture correlation (attributed from memory to
// Barrios, de Carvalho & Tavares 2011) could not be retrieved or even located for this project
// (docs/pbm.md "UFRJ: what is and is not from the literature" lists what was searched).
//   approximate: r_c = √(R x)           small-gap form of ball_ball (gap r²/R)
//   ball_ball:   r_c = √(R x − x²/4)    two balls of radius R, gap 2(R − √(R² − r²)) = x
//   ball_wall:   r_c = √(2 R x − x²)    a ball of radius R on a flat liner, gap R − √(R² − r²) = x
// ball_ball and ball_wall are capped at R (no larger gap exists); approximate is not capped, as
// before this choice existed.
namespace comminute::pbm {

enum class CaptureGeometry { approximate, ball_ball, ball_wall };

// ball_radius R and size x in m; the result in m.
double nip_capture_radius(CaptureGeometry g, double ball_radius, double x);

}  // namespace comminute::pbm
