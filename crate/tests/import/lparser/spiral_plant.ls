# Lparser example file 
# putting several ls files together to create a spiral plant

recursion 12
angle 30
thickness 100
min_thickness 5
shape 1
switch_yz 1

axiom [|ffff|?FFFF]&&&^D

rule D = AB!'DcZO
rule B = [---'''!:D]
rule A = &+^FLA

rule O = [!iw>>w>>w>>w>>w>>w]
rule w = [c(6)&{-f+f|-f+f}]
rule i = ;i

rule L = [--->c!!!!!!!1cl[a][b]]
rule a = [+a{.].C.}
rule b = [-b{.].C.}
rule C = gC
rule l = 'l
rule 1 = 2
rule 2 = 3
rule 3 = F

