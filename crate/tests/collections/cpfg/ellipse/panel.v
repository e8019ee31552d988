panel name: Viewing
background:512
size: 170 250

type: SLIDER
name: Color
colors: 513 514
origin: 20 180
min/max: 1 6
value: 1
message: n 2 1 0 %d

type: BUTTON
name: Color incr
colors: 515 516
origin: 35 140
value: 0
message: n 3 1 0 %d

type: SLIDER
name: Line width
colors: 513 514
origin: 20 60
min/max: 1 5
value: 2
message: n 4 1 0 %d

type: BUTTON
name: Width decr
colors: 515 516
origin: 35 20
value: 0
message: n 5 1 0 %d

