scale: 0.9000
z buffer: on
front distance: -10
back distance: 10
corrected rotation: on
