scale: 0.9000
correct rotation: on
