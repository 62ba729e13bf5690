# Relative RMS weight error against image size per estimator (estimators.tsv),
# mean +- sd over seeds: all bands (left) and the 6 finest bands (right).
set terminal pngcairo size 1400,600
set output dir.'/error.png'
set datafile separator "\t"
set datafile columnheaders
set logscale x 2
set xlabel 'image size (pixels per side)'
set yrange [0:*]
set key top right
f = dir.'/estimators.tsv'
# rows: 4 estimators per size, in this order
est(name, col) = strcol("estimator") eq name ? column(col) : NaN
set multiplot layout 1,2
set ylabel 'relative RMS weight error |w_{est} - w| / |w|, all bands'
plot f every 4::0 using "size":(est("eq12", "err_mean")):"err_sd" with yerrorlines lw 2 pt 7 title 'eq. 12 (paper)', \
     f every 4::1 using "size":(est("eq12_taper", "err_mean")):"err_sd" with yerrorlines lw 2 pt 5 title 'eq. 12, tapered DFT', \
     f every 4::2 using "size":(est("nnls_raw", "err_mean")):"err_sd" with yerrorlines lw 2 pt 9 title 'transfer matrix + NNLS, raw DFT', \
     f every 4::3 using "size":(est("corrected", "err_mean")):"err_sd" with yerrorlines lw 2 pt 11 title 'corrected (matrix + taper + NNLS)'
set ylabel 'relative RMS weight error, 6 finest bands'
plot f every 4::0 using "size":(est("eq12", "err_fine_mean")):"err_fine_sd" with yerrorlines lw 2 pt 7 title 'eq. 12 (paper)', \
     f every 4::1 using "size":(est("eq12_taper", "err_fine_mean")):"err_fine_sd" with yerrorlines lw 2 pt 5 title 'eq. 12, tapered DFT', \
     f every 4::2 using "size":(est("nnls_raw", "err_fine_mean")):"err_fine_sd" with yerrorlines lw 2 pt 9 title 'transfer matrix + NNLS, raw DFT', \
     f every 4::3 using "size":(est("corrected", "err_fine_mean")):"err_fine_sd" with yerrorlines lw 2 pt 11 title 'corrected (matrix + taper + NNLS)'
unset multiplot
