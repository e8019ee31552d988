scale: 0.9000
corrected rotation: on
