panel name: Water availability
background: 0
size: 210 80

type: SLIDER
name: Water
colors: 7 4
origin: 40 20
min/max: -16 0
value: -1
message: n 20 1 -4 %d
