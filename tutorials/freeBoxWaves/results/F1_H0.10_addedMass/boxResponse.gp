set terminal pngcairo size 1000,1100 font 'DejaVu Sans,10'
set output '/work/main/tutorials/freeBoxWaves/results/F1_H0.10_addedMass/boxResponse.png'
set termoption noenhanced
set multiplot layout 4,1 title "Free box, H = 0.1 m, T = 1.2 s: CFD (mesh factor 1, addedMass coupling) and Ren et al. (2015), the window grey"
set grid
set key top left opaque
set lmargin 10
set xrange [4.24242:12.6424]
set object 1 rect from 5.78432, graph 0 to 9.38432, graph 1 behind fc rgb '#e8e8e8' fs solid 1.0 noborder
set ylabel "elevation at x = 1 m (m)"
plot '/work/main/tutorials/freeBoxWaves/results/F1_H0.10_addedMass/series.dat' u 1:5 w l lw 1.6 lc rgb '#1f5fbf' t 'CFD', '/work/main/tutorials/freeBoxWaves/experiment/Ren2015data/H010WaveGauge' u ($1*1.2+5.44241865):($2*0.4+0) w lp pt 7 ps 0.5 lc rgb 'black' t 'experiment'
set ylabel "surge (m)"
plot '/work/main/tutorials/freeBoxWaves/results/F1_H0.10_addedMass/series.dat' u 1:2 w l lw 1.6 lc rgb '#1f5fbf' t 'CFD', '/work/main/tutorials/freeBoxWaves/experiment/Ren2015data/H010Surge' u ($1*1.2+5.44241865):($2*0.4+-0.015747534) w lp pt 7 ps 0.5 lc rgb 'black' t 'experiment + -0.0157 m'
set ylabel "heave (m)"
plot '/work/main/tutorials/freeBoxWaves/results/F1_H0.10_addedMass/series.dat' u 1:3 w l lw 1.6 lc rgb '#1f5fbf' t 'CFD', '/work/main/tutorials/freeBoxWaves/experiment/Ren2015data/H010Heave' u ($1*1.2+5.44241865):($2*0.4+0) w lp pt 7 ps 0.5 lc rgb 'black' t 'experiment'
set xlabel 't after the generator starts (s)'
set ylabel "pitch (deg)"
plot '/work/main/tutorials/freeBoxWaves/results/F1_H0.10_addedMass/series.dat' u 1:4 w l lw 1.6 lc rgb '#1f5fbf' t 'CFD', '/work/main/tutorials/freeBoxWaves/experiment/Ren2015data/H010Pitch' u ($1*1.2+5.44241865):($2*74.3705617+0) w lp pt 7 ps 0.5 lc rgb 'black' t 'experiment'
unset multiplot
