#version 3.7;
// Made with Meristem 0.1.0. Render: povray +Iplant.pov +Oplant.png +W800 +H600 +A0.3
global_settings { assumed_gamma 1.0 }
background { color rgb <1, 1, 1> }

#declare Meristem_Target = <0, 1.353553, 0>;
#declare Meristem_Eye = <1.277418, 2.273294, -5.10967>;
#declare Meristem_Aspect = image_width / image_height;
#declare Meristem_Half_Fov = radians(20);
camera {
  perspective
  location Meristem_Eye
  right x * Meristem_Aspect
  up y
  angle degrees(2 * atan(tan(Meristem_Half_Fov) * max(1, Meristem_Aspect)))
  look_at Meristem_Target
}
light_source { <-1.494535, 6.486836, -5.044221> color rgb <1, 1, 1> }
light_source { <5.471626, 1.219909, -4.250728> color rgb <0.35, 0.35, 0.35> shadowless }

#declare Meristem_Color_0 = texture { pigment { color rgb <0.4, 0.27, 0.15> } finish { ambient 0.15 diffuse 0.85 } }
#declare Meristem_Color_1 = texture { pigment { color rgb <0.44, 0.34, 0.17> } finish { ambient 0.15 diffuse 0.85 } }
#declare Meristem_Color_2 = texture { pigment { color rgb <0.43, 0.42, 0.18> } finish { ambient 0.15 diffuse 0.85 } }
#declare Meristem_Color_3 = texture { pigment { color rgb <0.36, 0.48, 0.16> } finish { ambient 0.15 diffuse 0.85 } }
#declare Meristem_Color_4 = texture { pigment { color rgb <0.27, 0.54, 0.15> } finish { ambient 0.15 diffuse 0.85 } }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.00726202 texture { Meristem_Color_0 } }
cylinder { <0, 1, 0>, <-0.707107, 1.707107, 0>, 0.00726202 texture { Meristem_Color_1 } }
cylinder { <-0.707107, 1.707107, 0>, <-1.707107, 1.707107, 0>, 0.00726202 texture { Meristem_Color_2 } }
cylinder { <-0.707107, 1.707107, 0>, <-0.707107, 2.707107, 0>, 0.00726202 texture { Meristem_Color_3 } }
cylinder { <0, 1, 0>, <0.707107, 1.707107, 0>, 0.00726202 texture { Meristem_Color_3 } }
cylinder { <0.707107, 1.707107, 0>, <1.707107, 1.707107, 0>, 0.00726202 texture { Meristem_Color_3 } }
cylinder { <0.707107, 1.707107, 0>, <0.707107, 2.707107, 0>, 0.00726202 texture { Meristem_Color_4 } }
