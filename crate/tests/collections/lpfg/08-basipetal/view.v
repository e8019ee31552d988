scale: 0.9000
