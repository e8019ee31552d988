target: Lsystem
panel name: View file
background: 0,0,0
size: 180 265
font: Arial,14,-1,5,50,0,0,0,0,0

type: SLIDER
name: Texture stretch 1 x 10
colors: 255,255,255 255,0,0
origin: 18 19
min/max: 0 100
value: 5
message: n 12 7 -1 %d

type: SLIDER
name: Texture stretch 2 x 10
colors: 255,255,255 255,0,0
origin: 18 76
min/max: 0 100
value: 10
message: n 13 7 -1 %d

type: SLIDER
name: Texture stretch 3 x 10
colors: 255,255,255 255,0,0
origin: 18 140
min/max: 0 100
value: 16
message: n 14 7 -1 %d

type: SLIDER
name: Texture stretch 4 x 10
colors: 255,255,255 255,0,0
origin: 18 201
min/max: 0 100
value: 7
message: n 15 7 -1 %d

type: MENU
name: 
message: d <name> %d <scale>
