<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>DesignReport</name>
    <message>
        <source>&lt;h1&gt;XY Tune design report&lt;/h1&gt;</source>
        <translation>&lt;h1&gt;Relatório de projeto do XY Tune&lt;/h1&gt;</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Data</translation>
    </message>
    <message>
        <source>XY Tune version</source>
        <translation>Versão do XY Tune</translation>
    </message>
    <message>
        <source>Session file</source>
        <translation>Arquivo da sessão</translation>
    </message>
    <message>
        <source>(unsaved session)</source>
        <translation>(sessão não salva)</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Eixo %1</translation>
    </message>
    <message>
        <source>%1%2</source>
        <translation>%1%2</translation>
    </message>
    <message>
        <source> (%1)</source>
        <translation> (%1)</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Verdict&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Veredito&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;span style=&apos;color:#1b7f2a&apos;&gt;✓&lt;/span&gt; Both axes meet the specification, as designed and as implemented.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;span style=&apos;color:#1b7f2a&apos;&gt;✓&lt;/span&gt; Os dois eixos atendem à especificação, tanto como projetados quanto como implementados.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;span style=&apos;color:#c62828&apos;&gt;✗&lt;/span&gt; The design fails the specification:&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;span style=&apos;color:#c62828&apos;&gt;✗&lt;/span&gt; O projeto não atende à especificação:&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Limits this design would meet: %1.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Limites que este projeto atenderia: %1.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>&lt;h2&gt;Specification&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Especificação&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>unit step: settling time (2 %) ≤ %1 s, overshoot ≤ %2 %</source>
        <translation>degrau unitário: tempo de acomodação (2 %) ≤ %1 s, sobressinal ≤ %2 %</translation>
    </message>
    <message>
        <source>tracking: max |e| ≤ %1 % of the travel, |u| ≤ %2 V and never clipped</source>
        <translation>seguimento: |e| máx ≤ %1 % do curso, |u| ≤ %2 V e nunca limitado</translation>
    </message>
    <message>
        <source>point-to-point move: settled into ±%1 mm within %2 s of its end</source>
        <translation>movimento ponto a ponto: acomodado em ±%1 mm até %2 s após o seu fim</translation>
    </message>
    <message>
        <source>loop margins: phase margin ≥ %1°, gain margin ≥ %2 dB (0: none stated)</source>
        <translation>margens da malha: margem de fase ≥ %1°, margem de ganho ≥ %2 dB (0: nenhuma exigida)</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Trajectory and implementation&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Trajetória e implementação&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>%1 move from %2 mm to %3 mm, from t = %4 s to %5 s</source>
        <translation>Movimento %1 de %2 mm a %3 mm, de t = %4 s a %5 s</translation>
    </message>
    <message>
        <source>Quintic</source>
        <translation>quíntico</translation>
    </message>
    <message>
        <source>Cubic</source>
        <translation>cúbico</translation>
    </message>
    <message>
        <source>Circle of radius %1 mm at %2 rad/s, ramp-in %3 s</source>
        <translation>Círculo de raio %1 mm a %2 rad/s, rampa de entrada de %3 s</translation>
    </message>
    <message>
        <source>G-code program %1, feed scale %2, max acceleration %3 mm/s², max jerk %4 mm/s³</source>
        <translation>Programa G-code %1, escala de avanço %2, aceleração máx %3 mm/s², jerk máx %4 mm/s³</translation>
    </message>
    <message>
        <source> (tracking time %1)</source>
        <translation> (tempo de rastreamento %1)</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Ti = kp/ki</source>
        <translation>Ti = kp/ki</translation>
    </message>
    <message>
        <source>Simulation: %1 (step %2 s)</source>
        <translation>Simulação: %1 (passo de %2 s)</translation>
    </message>
    <message>
        <source>Actuator limit: |u| ≤ %1 V</source>
        <translation>Limite do atuador: |u| ≤ %1 V</translation>
    </message>
    <message>
        <source>Digital PI: Ts = %1 s, %2 discretization; anti-windup %3</source>
        <translation>PI digital: Ts = %1 s, discretização %2; anti-windup %3</translation>
    </message>
    <message>
        <source>Computation delay %1 samples; encoder %2; DAC %3</source>
        <translation>Atraso de cálculo de %1 amostras; encoder %2; DAC %3</translation>
    </message>
    <message>
        <source>%1 mm per count</source>
        <translation>%1 mm por contagem</translation>
    </message>
    <message>
        <source>ideal</source>
        <translation>ideal</translation>
    </message>
    <message>
        <source>%1 bits over ±umax</source>
        <translation>%1 bits em ±umax</translation>
    </message>
    <message>
        <source>Axis %1 (%2)</source>
        <translation>Eixo %1 (%2)</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Figures against the specification&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;Valores frente à especificação&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Plots&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;Gráficos&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Plant&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;Planta&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>ARX model A(z&lt;sup&gt;−1&lt;/sup&gt;) y = B(z&lt;sup&gt;−1&lt;/sup&gt;) u at T&lt;sub&gt;s&lt;/sub&gt; = %1 s (position in mm, u in V)</source>
        <translation>Modelo ARX A(z&lt;sup&gt;−1&lt;/sup&gt;) y = B(z&lt;sup&gt;−1&lt;/sup&gt;) u com T&lt;sub&gt;s&lt;/sub&gt; = %1 s (posição em mm, u em V)</translation>
    </message>
    <message>
        <source>A = %1</source>
        <translation>A = %1</translation>
    </message>
    <message>
        <source>B = %1</source>
        <translation>B = %1</translation>
    </message>
    <message>
        <source>not a valid model: %1</source>
        <translation>modelo inválido: %1</translation>
    </message>
    <message>
        <source>G(s) = k&lt;sub&gt;0&lt;/sub&gt; / (s (s&lt;sup&gt;2&lt;/sup&gt; + a&lt;sub&gt;1&lt;/sub&gt; s + a&lt;sub&gt;2&lt;/sub&gt;)), k&lt;sub&gt;0&lt;/sub&gt; = %1, a&lt;sub&gt;1&lt;/sub&gt; = %2, a&lt;sub&gt;2&lt;/sub&gt; = %3</source>
        <translation>G(s) = k&lt;sub&gt;0&lt;/sub&gt; / (s (s&lt;sup&gt;2&lt;/sup&gt; + a&lt;sub&gt;1&lt;/sub&gt; s + a&lt;sub&gt;2&lt;/sub&gt;)), k&lt;sub&gt;0&lt;/sub&gt; = %1, a&lt;sub&gt;1&lt;/sub&gt; = %2, a&lt;sub&gt;2&lt;/sub&gt; = %3</translation>
    </message>
    <message>
        <source>model units per mm of trajectory: %1</source>
        <translation>unidades do modelo por mm de trajetória: %1</translation>
    </message>
    <message>
        <source>flexible mode: %1 Hz, damping %2</source>
        <translation>modo flexível: %1 Hz, amortecimento %2</translation>
    </message>
    <message>
        <source>; anti-resonance %1 Hz, damping %2</source>
        <translation>; antirressonância %1 Hz, amortecimento %2</translation>
    </message>
    <message>
        <source>as every run and analysis sees it: G(s) = (%1) / (%2)</source>
        <translation>como toda simulação e análise a vê: G(s) = (%1) / (%2)</translation>
    </message>
    <message>
        <source>not a valid plant: %1</source>
        <translation>planta inválida: %1</translation>
    </message>
    <message>
        <source>identified as %1 from %2 (%3 samples at %4 s), fit %5 %</source>
        <translation>identificada como %1 a partir de %2 (%3 amostras a %4 s), ajuste de %5 %</translation>
    </message>
    <message>
        <source>, on validation data %1 %</source>
        <translation>, nos dados de validação %1 %</translation>
    </message>
    <message>
        <source>entered by hand: the session records no identification</source>
        <translation>inserida manualmente: a sessão não registra identificação</translation>
    </message>
    <message>
        <source>table friction: Coulomb %1 V, static %2 V, viscous %3 V per mm/s, backlash %4 mm, amplifier deadband %5 V; friction compensation %6 % (band %7 mm/s)</source>
        <translation>atrito da mesa: Coulomb %1 V, estático %2 V, viscoso %3 V por mm/s, folga %4 mm, zona morta do amplificador %5 V; compensação de atrito %6 % (faixa de %7 mm/s)</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Design: %1&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;Projeto: %1&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>ω&lt;sub&gt;n&lt;/sub&gt; = %1 rad/s</source>
        <translation>ω&lt;sub&gt;n&lt;/sub&gt; = %1 rad/s</translation>
    </message>
    <message>
        <source>k&lt;sub&gt;p&lt;/sub&gt; = %1</source>
        <translation>k&lt;sub&gt;p&lt;/sub&gt; = %1</translation>
    </message>
    <message>
        <source>T = 1 + t&lt;sub&gt;1&lt;/sub&gt; z&lt;sup&gt;−1&lt;/sup&gt;, t&lt;sub&gt;1&lt;/sub&gt; = %1</source>
        <translation>T = 1 + t&lt;sub&gt;1&lt;/sub&gt; z&lt;sup&gt;−1&lt;/sup&gt;, t&lt;sub&gt;1&lt;/sub&gt; = %1</translation>
    </message>
    <message>
        <source>T&lt;sub&gt;s&lt;/sub&gt; = %1 s</source>
        <translation>T&lt;sub&gt;s&lt;/sub&gt; = %1 s</translation>
    </message>
    <message>
        <source>ZPETC feedforward on</source>
        <translation>pré-alimentação ZPETC ligada</translation>
    </message>
    <message>
        <source>ZPETC feedforward off</source>
        <translation>pré-alimentação ZPETC desligada</translation>
    </message>
    <message>
        <source>%1 = %2 %3</source>
        <translation>%1 = %2 %3</translation>
    </message>
    <message>
        <source>&lt;p&gt;Settings: %1&lt;/p&gt;</source>
        <translation>&lt;p&gt;Configurações: %1&lt;/p&gt;</translation>
    </message>
    <message>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;No design&lt;/b&gt;: %1: %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Sem projeto&lt;/b&gt;: %1: %2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Coefficients of the design:&lt;/p&gt;</source>
        <translation>&lt;p&gt;Coeficientes do projeto:&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;tr style=&apos;background:#dddddd&apos;&gt;&lt;th&gt;Name&lt;/th&gt;&lt;th&gt;Value&lt;/th&gt;&lt;th&gt;Unit&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr style=&apos;background:#dddddd&apos;&gt;&lt;th&gt;Nome&lt;/th&gt;&lt;th&gt;Valor&lt;/th&gt;&lt;th&gt;Unidade&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Controller&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;Controlador&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>digital PI at T&lt;sub&gt;s&lt;/sub&gt; = %1 s (%2): C(z) = (%3) / (%4)</source>
        <translation>PI digital com T&lt;sub&gt;s&lt;/sub&gt; = %1 s (%2): C(z) = (%3) / (%4)</translation>
    </message>
    <message>
        <source>difference equation: %1, e = r − y</source>
        <translation>equação de diferenças: %1, e = r − y</translation>
    </message>
    <message>
        <source>num = [%1], den = [%2] (ascending powers of z&lt;sup&gt;−1&lt;/sup&gt;)</source>
        <translation>num = [%1], den = [%2] (potências crescentes de z&lt;sup&gt;−1&lt;/sup&gt;)</translation>
    </message>
    <message>
        <source>notch at %1 Hz, width %2 Hz, depth %3 dB on the error: N(s) = (%4) / (%5); biquad b = [%6], a = [1, %7, %8] (bilinear, prewarped)</source>
        <translation>notch em %1 Hz, largura %2 Hz, profundidade %3 dB no erro: N(s) = (%4) / (%5); biquad b = [%6], a = [1, %7, %8] (bilinear, com pré-distorção)</translation>
    </message>
    <message>
        <source>no digital controller: %1</source>
        <translation>sem controlador digital: %1</translation>
    </message>
    <message>
        <source>the RST law above runs as designed, at T&lt;sub&gt;s&lt;/sub&gt; = %1 s</source>
        <translation>a lei RST acima é executada como projetada, com T&lt;sub&gt;s&lt;/sub&gt; = %1 s</translation>
    </message>
    <message>
        <source>the method&apos;s step runs at T&lt;sub&gt;s&lt;/sub&gt; = %1 s (File › Export › Firmware C header)</source>
        <translation>o passo do método é executado com T&lt;sub&gt;s&lt;/sub&gt; = %1 s (Arquivo › Exportar › Cabeçalho C para firmware)</translation>
    </message>
    <message>
        <source>digital loop: least damping of its z-plane poles %1 (the design&apos;s %2)</source>
        <translation>malha digital: menor amortecimento dos seus polos no plano z %1 (o do projeto: %2)</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Digital implementation&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Implementação digital&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>no design: %1: %2</source>
        <translation>sem projeto: %1: %2</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Warnings&lt;/h3&gt;&lt;p&gt;None.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Avisos&lt;/h3&gt;&lt;p&gt;Nenhum.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Warnings&lt;/h3&gt;</source>
        <translation>&lt;h3&gt;Avisos&lt;/h3&gt;</translation>
    </message>
    <message>
        <source>&lt;h2 style=&apos;page-break-before: always&apos;&gt;Both axes: the XY contour&lt;/h2&gt;</source>
        <translation>&lt;h2 style=&apos;page-break-before: always&apos;&gt;Os dois eixos: o contorno XY&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>radial error of the circle: max %1 mm, RMS %2 mm</source>
        <translation>erro radial do círculo: máx %1 mm, RMS %2 mm</translation>
    </message>
    <message>
        <source>contour error of the program: max %1 mm, RMS %2 mm</source>
        <translation>erro de contorno do programa: máx %1 mm, RMS %2 mm</translation>
    </message>
    <message>
        <source>ISO 230-4: circular deviation G %1 mm, radial deviation F max %2 mm, F min %3 mm</source>
        <translation>ISO 230-4: desvio circular G %1 mm, desvio radial F máx %2 mm, F mín %3 mm</translation>
    </message>
    <message>
        <source>program: %1</source>
        <translation>programa: %1</translation>
    </message>
    <message>
        <source>input shaper %1 on the reference at %2 Hz, damping %3</source>
        <translation>modelador de entrada %1 na referência em %2 Hz, amortecimento %3</translation>
    </message>
    <message>
        <source>; axis %1: residual vibration %2 mm shaped, %3 mm unshaped</source>
        <translation>; eixo %1: vibração residual de %2 mm com modelagem, %3 mm sem modelagem</translation>
    </message>
    <message>
        <source>cross-coupled contouring controller (Koren): k&lt;sub&gt;p&lt;/sub&gt; = %1 V/mm, k&lt;sub&gt;i&lt;/sub&gt; = %2 V/(mm s), %3 contour estimate</source>
        <translation>controlador de contorno com acoplamento cruzado (Koren): k&lt;sub&gt;p&lt;/sub&gt; = %1 V/mm, k&lt;sub&gt;i&lt;/sub&gt; = %2 V/(mm s), estimativa de contorno %3</translation>
    </message>
    <message>
        <source>cross-coupling: %1</source>
        <translation>acoplamento cruzado: %1</translation>
    </message>
</context>
<context>
    <name>FoldButton</name>
    <message>
        <source>%1: click to show or hide these settings</source>
        <translation>%1: clique para mostrar ou ocultar estas configurações</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>ITAE</source>
        <translation>ITAE</translation>
    </message>
    <message>
        <source>max |e|</source>
        <translation>máx |e|</translation>
    </message>
    <message>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <source>max |u|</source>
        <translation>máx |u|</translation>
    </message>
    <message>
        <source>settle time</source>
        <translation>tempo de acomodação</translation>
    </message>
    <message>
        <source>phase margin</source>
        <translation>margem de fase</translation>
    </message>
    <message>
        <source>gain margin</source>
        <translation>margem de ganho</translation>
    </message>
    <message>
        <source>mm·s²</source>
        <translation>mm·s²</translation>
    </message>
    <message>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <source>s after tf</source>
        <translation>s após tf</translation>
    </message>
    <message>
        <source>deg, larger is better</source>
        <translation>graus, maior é melhor</translation>
    </message>
    <message>
        <source>dB, larger is better</source>
        <translation>dB, maior é melhor</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>%1%2 (%3)</source>
        <translation>%1%2 (%3)</translation>
    </message>
    <message>
        <source> ∫t|e|dt</source>
        <translation> ∫t|e|dt</translation>
    </message>
    <message>
        <source>Could not write %1</source>
        <translation>Não foi possível gravar %1</translation>
    </message>
    <message>
        <source>Save plot</source>
        <translation>Salvar gráfico</translation>
    </message>
    <message>
        <source>PNG image (*.png);;PDF document (*.pdf)</source>
        <translation>Imagem PNG (*.png);;Documento PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Restaurar vista</translation>
    </message>
    <message>
        <source>Save as PNG...</source>
        <translation>Salvar como PNG...</translation>
    </message>
    <message>
        <source>Save as PDF...</source>
        <translation>Salvar como PDF...</translation>
    </message>
    <message>
        <source>breaks spec</source>
        <translation>viola a especificação</translation>
    </message>
    <message>
        <source>ζ = 1 (Mp 0 %)</source>
        <translation>ζ = 1 (Mp 0 %)</translation>
    </message>
    <message>
        <source>ζ ≥ %1 (Mp %2 %)</source>
        <translation>ζ ≥ %1 (Mp %2 %)</translation>
    </message>
    <message>
        <source>|z| ≤ %1 (ts %2 s)</source>
        <translation>|z| ≤ %1 (ts %2 s)</translation>
    </message>
    <message>
        <source>σ ≤ %1 (ts %2 s)</source>
        <translation>σ ≤ %1 (ts %2 s)</translation>
    </message>
    <message>
        <source>reference model ωn %1</source>
        <translation>modelo de referência ωn %1</translation>
    </message>
    <message>
        <source>dominant poles: ωn %1 rad/s, ζ %2</source>
        <translation>polos dominantes: ωn %1 rad/s, ζ %2</translation>
    </message>
    <message>
        <source>closed-loop unit step</source>
        <translation>degrau unitário em malha fechada</translation>
    </message>
    <message>
        <source>loop alone Kf B/T</source>
        <translation>só a malha Kf B/T</translation>
    </message>
    <message>
        <source>loop alone (no ZPETC)</source>
        <translation>só a malha (sem ZPETC)</translation>
    </message>
    <message>
        <source>with ZPETC</source>
        <translation>com ZPETC</translation>
    </message>
    <message>
        <source>with ZPETC (off)</source>
        <translation>com ZPETC (desligado)</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>n/d</translation>
    </message>
    <message>
        <source>the axis has no loop to analyse</source>
        <translation>o eixo não tem malha para analisar</translation>
    </message>
    <message>
        <source>an untitled session</source>
        <translation>uma sessão sem título</translation>
    </message>
    <message>
        <source>“%1”</source>
        <translation>“%1”</translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation>Recuperar trabalho não salvo</translation>
    </message>
    <message>
        <source>XY Tune was closed without saving changes to %1 (last kept %2).

Restore that work?</source>
        <translation>O XY Tune foi fechado sem salvar as alterações em %1 (guardadas pela última vez em %2).

Restaurar esse trabalho?</translation>
    </message>
    <message>
        <source>&amp;Restore</source>
        <translation>&amp;Restaurar</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>&amp;Descartar</translation>
    </message>
    <message>
        <source>Restore unsaved work</source>
        <translation>Restaurar trabalho não salvo</translation>
    </message>
    <message>
        <source>live view simulated at dt = %1 s, not %2 s: %3 samples exceed the live limit of %4 (the exports and the report use dt = %2 s)</source>
        <translation>vista ao vivo simulada com dt = %1 s, não %2 s: %3 amostras excedem o limite ao vivo de %4 (as exportações e o relatório usam dt = %2 s)</translation>
    </message>
    <message>
        <source>ωn = %1 rad/s, kp = %2</source>
        <translation>ωn = %1 rad/s, kp = %2</translation>
    </message>
    <message>
        <source>pole placement, t1 = %1, Ts = %2 s%3</source>
        <translation>alocação de polos, t1 = %1, Ts = %2 s%3</translation>
    </message>
    <message>
        <source>, ZPETC</source>
        <translation>, ZPETC</translation>
    </message>
    <message>
        <source>plant k0 = %1, a1 = %2, a2 = %3</source>
        <translation>planta k0 = %1, a1 = %2, a2 = %3</translation>
    </message>
    <message>
        <source>not computed (the study was cancelled)</source>
        <translation>não calculado (o estudo foi cancelado)</translation>
    </message>
    <message>
        <source>unstable closed loop</source>
        <translation>malha fechada instável</translation>
    </message>
    <message>
        <source>the run diverged</source>
        <translation>a simulação divergiu</translation>
    </message>
    <message>
        <source>settling %1 s &gt; %2 s</source>
        <translation>acomodação %1 s &gt; %2 s</translation>
    </message>
    <message>
        <source>overshoot %1 % &gt; %2 %</source>
        <translation>sobressinal %1 % &gt; %2 %</translation>
    </message>
    <message>
        <source>|u| saturates at %1 V</source>
        <translation>|u| satura em %1 V</translation>
    </message>
    <message>
        <source>|u| %1 V &gt; %2 V</source>
        <translation>|u| %1 V &gt; %2 V</translation>
    </message>
    <message>
        <source>phase margin %1° &lt; %2°</source>
        <translation>margem de fase %1° &lt; %2°</translation>
    </message>
    <message>
        <source>gain margin %1 dB &lt; %2 dB</source>
        <translation>margem de ganho %1 dB &lt; %2 dB</translation>
    </message>
    <message>
        <source>max error %1 % &gt; %2 %</source>
        <translation>erro máx %1 % &gt; %2 %</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>ωn = %1 rad/s   kp = %2   %3 = %4   feasible: %5</source>
        <translation>ωn = %1 rad/s   kp = %2   %3 = %4   viável: %5</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sim</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
    </message>
    <message>
        <source>
fails: %1</source>
        <translation>
falha: %1</translation>
    </message>
    <message>
        <source>colour: the metric, by the scale at the right (yellow is the high end, better only for the margins) · unveiled and outlined: feasible · veiled: infeasible · grey: unstable or diverged · light grey: not computed (cancelled)</source>
        <translation>cor: a métrica, pela escala à direita (amarelo é o extremo alto, melhor só para as margens) · sem véu e contornado: viável · com véu: inviável · cinza: instável ou divergente · cinza-claro: não calculado (cancelado)</translation>
    </message>
    <message>
        <source>within ±bound</source>
        <translation>dentro de ±limite</translation>
    </message>
    <message>
        <source>%1 lags outside</source>
        <translation>%1 atrasos fora</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>kp %1 V/mm, ki %2 V/(mm·s)</source>
        <translation>kp %1 V/mm, ki %2 V/(mm·s)</translation>
    </message>
    <message>
        <source>circular</source>
        <translation>circular</translation>
    </message>
    <message>
        <source>linear</source>
        <translation>linear</translation>
    </message>
    <message>
        <source>the G-code program</source>
        <translation>o programa G-code</translation>
    </message>
    <message>
        <source>the program %1</source>
        <translation>o programa %1</translation>
    </message>
    <message>
        <source>the %1 mm circle</source>
        <translation>o círculo de %1 mm</translation>
    </message>
    <message>
        <source>the point-to-point move</source>
        <translation>o movimento ponto a ponto</translation>
    </message>
    <message>
        <source>The contour of %1, run once for each pair of gains with the axes, the limit and the %2 estimate of the session as it is when the sweep starts.</source>
        <translation>O contorno de %1, simulado uma vez para cada par de ganhos com os eixos, o limite e a estimativa %2 da sessão como está quando a varredura começa.</translation>
    </message>
    <message>
        <source>the actuator limit, %1 V then</source>
        <translation>o limite do atuador, %1 V naquele momento</translation>
    </message>
    <message>
        <source>axis %1</source>
        <translation>eixo %1</translation>
    </message>
    <message>
        <source>the trajectory</source>
        <translation>a trajetória</translation>
    </message>
    <message>
        <source>the coupling&apos;s estimate</source>
        <translation>a estimativa do acoplamento</translation>
    </message>
    <message>
        <source>the specification</source>
        <translation>a especificação</translation>
    </message>
    <message>
        <source>the implementation</source>
        <translation>a implementação</translation>
    </message>
    <message>
        <source>%1 design</source>
        <translation>projeto %1</translation>
    </message>
    <message>
        <source>%1 closed-loop poles</source>
        <translation>polos de malha fechada %1</translation>
    </message>
    <message>
        <source>%1 RMSE (mm)</source>
        <translation>%1 RMSE (mm)</translation>
    </message>
    <message>
        <source>%1 max |e| (mm)</source>
        <translation>%1 máx |e| (mm)</translation>
    </message>
    <message>
        <source>%1 max |u| (V)</source>
        <translation>%1 máx |u| (V)</translation>
    </message>
    <message>
        <source>%1 settling (s)</source>
        <translation>%1 acomodação (s)</translation>
    </message>
    <message>
        <source>unstable</source>
        <translation>instável</translation>
    </message>
    <message>
        <source>%1 overshoot (%)</source>
        <translation>%1 sobressinal (%)</translation>
    </message>
    <message>
        <source>%1 ITAE</source>
        <translation>%1 ITAE</translation>
    </message>
</context>
<context>
    <name>ReportMetrics</name>
    <message>
        <source>n/a</source>
        <translation>n/d</translation>
    </message>
    <message>
        <source>&gt; %1 (not settled in the run)</source>
        <translation>&gt; %1 (não acomodou na simulação)</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
    </message>
    <message>
        <source>&lt;p&gt;No figures: the axis has no design (%1: %2).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Sem valores: o eixo não tem projeto (%1: %2).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>≤ %1</source>
        <translation>≤ %1</translation>
    </message>
    <message>
        <source> (flagged, not applied)</source>
        <translation> (sinalizado, não aplicado)</translation>
    </message>
    <message>
        <source>|e| ≤ %1</source>
        <translation>|e| ≤ %1</translation>
    </message>
    <message>
        <source>same step</source>
        <translation>mesmo degrau</translation>
    </message>
    <message>
        <source>unstable</source>
        <translation>instável</translation>
    </message>
    <message>
        <source>same loop</source>
        <translation>mesma malha</translation>
    </message>
    <message>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <source>&lt;tr style=&apos;background:#dddddd&apos;&gt;&lt;th align=&apos;left&apos;&gt;Figure&lt;/th&gt;&lt;th&gt;Limit&lt;/th&gt;&lt;th&gt;As designed&lt;/th&gt;&lt;th&gt;As implemented%1&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr style=&apos;background:#dddddd&apos;&gt;&lt;th align=&apos;left&apos;&gt;Valor&lt;/th&gt;&lt;th&gt;Limite&lt;/th&gt;&lt;th&gt;Como projetado&lt;/th&gt;&lt;th&gt;Como implementado%1&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source> (digital, Ts = %1 s)</source>
        <translation> (digital, Ts = %1 s)</translation>
    </message>
</context>
<context>
    <name>ReportWriter</name>
    <message>
        <source>Cannot write the report to %1: %2</source>
        <translation>Não é possível gravar o relatório em %1: %2</translation>
    </message>
    <message>
        <source>No report: the session&apos;s run is refused: %1: %2</source>
        <translation>Sem relatório: a simulação da sessão foi recusada: %1: %2</translation>
    </message>
    <message>
        <source>XY Tune design report</source>
        <translation>Relatório de projeto do XY Tune</translation>
    </message>
    <message>
        <source>XY Tune %1</source>
        <translation>XY Tune %1</translation>
    </message>
</context>
<context>
    <name>analysis_a0_nonzero</name>
    <message>
        <source>A(0) must be nonzero</source>
        <translation>A(0) deve ser diferente de zero</translation>
    </message>
</context>
<context>
    <name>analysis_above_nyquist</name>
    <message>
        <source>above the Nyquist frequency pi/Ts</source>
        <translation>acima da frequência de Nyquist pi/Ts</translation>
    </message>
</context>
<context>
    <name>analysis_above_nyquist_discrete</name>
    <message>
        <source>above the Nyquist frequency pi/Ts of a discrete system</source>
        <translation>acima da frequência de Nyquist pi/Ts de um sistema discreto</translation>
    </message>
</context>
<context>
    <name>analysis_above_omega_min</name>
    <message>
        <source>must be above omegaMin</source>
        <translation>deve ser maior que omegaMin</translation>
    </message>
</context>
<context>
    <name>analysis_axes_periods_differ</name>
    <message>
        <source>the two axes&apos; models must have the same period</source>
        <translation>os modelos dos dois eixos devem ter o mesmo período</translation>
    </message>
</context>
<context>
    <name>analysis_b0_zero</name>
    <message>
        <source>B(0) must be 0 (a delay of at least one sample)</source>
        <translation>B(0) deve ser 0 (um atraso de pelo menos uma amostra)</translation>
    </message>
</context>
<context>
    <name>analysis_below_degree</name>
    <message>
        <source>must be at least the degree of the polynomial</source>
        <translation>deve ser pelo menos o grau do polinômio</translation>
    </message>
</context>
<context>
    <name>analysis_damping_ratios_range</name>
    <message>
        <source>each damping ratio must be in [0, 1]</source>
        <translation>cada coeficiente de amortecimento deve estar em [0, 1]</translation>
    </message>
</context>
<context>
    <name>analysis_discretization_overflows</name>
    <message>
        <source>the exact discretization overflows double precision (a very fast pole): use a shorter period</source>
        <translation>a discretização exata estoura a precisão dupla (um polo muito rápido): use um período menor</translation>
    </message>
</context>
<context>
    <name>analysis_exceeds_nyquist</name>
    <message>
        <source>must not exceed the Nyquist frequency pi/Ts</source>
        <translation>não deve exceder a frequência de Nyquist pi/Ts</translation>
    </message>
</context>
<context>
    <name>analysis_f0_nonzero</name>
    <message>
        <source>F(0) must be nonzero</source>
        <translation>F(0) deve ser diferente de zero</translation>
    </message>
</context>
<context>
    <name>analysis_finite_above_one</name>
    <message>
        <source>must be a finite number &gt; 1</source>
        <translation>deve ser um número finito &gt; 1</translation>
    </message>
</context>
<context>
    <name>analysis_finite_above_zero</name>
    <message>
        <source>must be a finite number &gt; 0</source>
        <translation>deve ser um número finito &gt; 0</translation>
    </message>
</context>
<context>
    <name>analysis_finite_and_not_negative</name>
    <message>
        <source>must be finite and &gt;= 0</source>
        <translation>deve ser finito e &gt;= 0</translation>
    </message>
</context>
<context>
    <name>analysis_frequencies_not_negative</name>
    <message>
        <source>frequencies must be &gt;= 0</source>
        <translation>as frequências devem ser &gt;= 0</translation>
    </message>
</context>
<context>
    <name>analysis_in_integer_range</name>
    <message>
        <source>must be in %1..%2</source>
        <translation>deve estar em %1..%2</translation>
    </message>
</context>
<context>
    <name>analysis_in_open_range</name>
    <message>
        <source>must be in (%1, %2)</source>
        <translation>deve estar em (%1, %2)</translation>
    </message>
</context>
<context>
    <name>analysis_in_range_open_left</name>
    <message>
        <source>must be in (%1, %2]</source>
        <translation>deve estar em (%1, %2]</translation>
    </message>
</context>
<context>
    <name>analysis_kmax_range</name>
    <message>
        <source>must be finite and &gt;= 0 (0: automatic)</source>
        <translation>deve ser finito e &gt;= 0 (0: automático)</translation>
    </message>
</context>
<context>
    <name>analysis_locus_biproper_infinity</name>
    <message>
        <source>the loop is biproper and d_n + K n_n vanishes at K = %1: a root passes through infinity</source>
        <translation>a malha é biprópria e d_n + K n_n se anula em K = %1: uma raiz passa pelo infinito</translation>
    </message>
</context>
<context>
    <name>analysis_locus_cancellation</name>
    <message>
        <source>near pole-zero cancellation at %1: that branch has (almost) no length</source>
        <translation>quase cancelamento polo-zero em %1: esse ramo tem comprimento (quase) nulo</translation>
    </message>
</context>
<context>
    <name>analysis_locus_gain_limit</name>
    <message>
        <source>stopped at K &gt; 1e250 before every branch converged</source>
        <translation>parou em K &gt; 1e250 antes de todos os ramos convergirem</translation>
    </message>
</context>
<context>
    <name>analysis_locus_improper</name>
    <message>
        <source>degree %1 exceeds the denominator&apos;s %2: the loop is improper</source>
        <translation>o grau %1 excede o do denominador, %2: a malha é imprópria</translation>
    </message>
</context>
<context>
    <name>analysis_locus_no_poles</name>
    <message>
        <source>must have degree &gt;= 1 (a loop without poles has no locus)</source>
        <translation>deve ter grau &gt;= 1 (uma malha sem polos não tem lugar das raízes)</translation>
    </message>
</context>
<context>
    <name>analysis_locus_point_limit</name>
    <message>
        <source>stopped at the point limit (%1) at K = %2 before every branch converged</source>
        <translation>parou no limite de pontos (%1) em K = %2 antes de todos os ramos convergirem</translation>
    </message>
</context>
<context>
    <name>analysis_locus_poles_ill_conditioned</name>
    <message>
        <source>the open-loop poles near %1 are ill-conditioned (clustered or multiple roots): round-off alone can move them by about %2 of their size, so they and the locus near them may be wrong</source>
        <translation>os polos de malha aberta perto de %1 são mal condicionados (raízes agrupadas ou múltiplas): o arredondamento sozinho pode movê-los em cerca de %2 do seu tamanho, então eles e o lugar das raízes perto deles podem estar errados</translation>
    </message>
</context>
<context>
    <name>analysis_locus_sample_skipped</name>
    <message>
        <source>%1 = %2: skipped, the pole count changed</source>
        <translation>%1 = %2: ignorado, o número de polos mudou</translation>
    </message>
</context>
<context>
    <name>analysis_locus_step_bound</name>
    <message>
        <source>the step bound could not be met near K = %1</source>
        <translation>o limite de passo não pôde ser respeitado perto de K = %1</translation>
    </message>
</context>
<context>
    <name>analysis_locus_time_bound</name>
    <message>
        <source>stopped at the time bound (%1 s, %2 points) at K = %3 before every branch converged: its roots are hard to find (an ill-conditioned loop)</source>
        <translation>parou no limite de tempo (%1 s, %2 pontos) em K = %3 antes de todos os ramos convergirem: suas raízes são difíceis de encontrar (uma malha mal condicionada)</translation>
    </message>
</context>
<context>
    <name>analysis_locus_work_bound</name>
    <message>
        <source>stopped at the work bound (about %1 million operations, %2 points) at K = %3 before every branch converged: the loop&apos;s order %4 makes each point expensive</source>
        <translation>parou no limite de trabalho (cerca de %1 milhões de operações, %2 pontos) em K = %3 antes de todos os ramos convergirem: a ordem %4 da malha torna cada ponto caro</translation>
    </message>
</context>
<context>
    <name>analysis_locus_zero_numerator</name>
    <message>
        <source>the numerator is zero: there is no locus</source>
        <translation>o numerador é zero: não há lugar das raízes</translation>
    </message>
</context>
<context>
    <name>analysis_locus_zeros_ill_conditioned</name>
    <message>
        <source>the open-loop zeros near %1 are ill-conditioned (clustered or multiple roots): round-off alone can move them by about %2 of their size, so they and the locus near them may be wrong</source>
        <translation>os zeros de malha aberta perto de %1 são mal condicionados (raízes agrupadas ou múltiplas): o arredondamento sozinho pode movê-los em cerca de %2 do seu tamanho, então eles e o lugar das raízes perto deles podem estar errados</translation>
    </message>
</context>
<context>
    <name>analysis_loop_improper</name>
    <message>
        <source>the loop is improper (more zeros than poles)</source>
        <translation>a malha é imprópria (mais zeros que polos)</translation>
    </message>
</context>
<context>
    <name>analysis_margins_closed_loop_unstable</name>
    <message>
        <source>the closed loop is unstable: the margins and peaks describe the frequency response, not robustness</source>
        <translation>a malha fechada é instável: as margens e os picos descrevem a resposta em frequência, não a robustez</translation>
    </message>
</context>
<context>
    <name>analysis_model_has_no_state</name>
    <message>
        <source>has no state</source>
        <translation>não tem estado</translation>
    </message>
</context>
<context>
    <name>analysis_model_not_finite</name>
    <message>
        <source>has a coefficient that is not a finite number</source>
        <translation>tem um coeficiente que não é um número finito</translation>
    </message>
</context>
<context>
    <name>analysis_model_sizes_disagree</name>
    <message>
        <source>phi (%1 x %2), gamma (%3) and c (%4) sizes disagree</source>
        <translation>os tamanhos de phi (%1 x %2), gamma (%3) e c (%4) não concordam</translation>
    </message>
</context>
<context>
    <name>analysis_number_not_negative</name>
    <message>
        <source>must be a number &gt;= 0</source>
        <translation>deve ser um número &gt;= 0</translation>
    </message>
</context>
<context>
    <name>analysis_nyquist_fractional_turns</name>
    <message>
        <source>the curve&apos;s turn around -1 is not a whole number of turns</source>
        <translation>a volta da curva em torno de -1 não é um número inteiro de voltas</translation>
    </message>
</context>
<context>
    <name>analysis_nyquist_sampling_bound</name>
    <message>
        <source>the sampling bound was reached near a sharp turn of the curve: the encirclement count may be wrong</source>
        <translation>o limite de amostragem foi atingido perto de uma curva acentuada: a contagem de envolvimentos pode estar errada</translation>
    </message>
</context>
<context>
    <name>analysis_nyquist_through_minus_one</name>
    <message>
        <source>the curve passes through -1: a closed-loop pole lies on the stability boundary, the encirclement count is not defined</source>
        <translation>a curva passa por -1: um polo de malha fechada está na fronteira de estabilidade, a contagem de envolvimentos não é definida</translation>
    </message>
</context>
<context>
    <name>analysis_positive</name>
    <message>
        <source>must be positive</source>
        <translation>deve ser positivo</translation>
    </message>
</context>
<context>
    <name>analysis_return_difference_zero</name>
    <message>
        <source>1 + L is zero (L = -1)</source>
        <translation>1 + L é zero (L = -1)</translation>
    </message>
</context>
<context>
    <name>analysis_swept_values_not_positive</name>
    <message>
        <source>the swept values must be &gt; 0</source>
        <translation>os valores da varredura devem ser &gt; 0</translation>
    </message>
</context>
<context>
    <name>analysis_to_equals_from</name>
    <message>
        <source>must differ from &apos;from&apos;</source>
        <translation>deve ser diferente de &apos;from&apos;</translation>
    </message>
</context>
<context>
    <name>analysis_ts_range</name>
    <message>
        <source>must be finite and &gt;= 0 (0: continuous)</source>
        <translation>deve ser finito e &gt;= 0 (0: contínuo)</translation>
    </message>
</context>
<context>
    <name>analysis_view_empty</name>
    <message>
        <source>needs reMin &lt; reMax and imMin &lt; imMax</source>
        <translation>exige reMin &lt; reMax e imMin &lt; imMax</translation>
    </message>
</context>
<context>
    <name>at_least</name>
    <message>
        <source>must be at least %1</source>
        <translation>deve ser pelo menos %1</translation>
    </message>
</context>
<context>
    <name>circle_too_short</name>
    <message>
        <source>the circle lasts fewer than 3 samples: no ISO 230-4 figures</source>
        <translation>o círculo dura menos de 3 amostras: sem valores ISO 230-4</translation>
    </message>
</context>
<context>
    <name>closed_loop_unstable</name>
    <message>
        <source>the closed loop is unstable</source>
        <translation>a malha fechada é instável</translation>
    </message>
</context>
<context>
    <name>contour_accel_too_long</name>
    <message>
        <source>%5 mm/s^2 needs at least %1 to move the path&apos;s %6 mm from rest to rest (2 sqrt(L / A)), more than the %2 samples at dt %3 s hold (%4)</source>
        <translation>%5 mm/s^2 precisa de pelo menos %1 para percorrer os %6 mm do caminho de repouso a repouso (2 sqrt(L / A)), mais do que comportam as %2 amostras com dt %3 s (%4)</translation>
    </message>
</context>
<context>
    <name>contour_arc_length_overflows</name>
    <message>
        <source>an arc&apos;s length overflows a double</source>
        <translation>o comprimento de um arco excede a faixa de um double</translation>
    </message>
</context>
<context>
    <name>contour_arc_not_finite</name>
    <message>
        <source>an arc&apos;s centre, radius and angles must be finite numbers</source>
        <translation>o centro, o raio e os ângulos de um arco devem ser números finitos</translation>
    </message>
</context>
<context>
    <name>contour_arc_radius_not_positive</name>
    <message>
        <source>an arc&apos;s radius must be greater than zero</source>
        <translation>o raio de um arco deve ser maior que zero</translation>
    </message>
</context>
<context>
    <name>contour_arc_sweep</name>
    <message>
        <source>an arc&apos;s sweep must be nonzero and at most one turn</source>
        <translation>a varredura angular de um arco deve ser não nula e de no máximo uma volta</translation>
    </message>
</context>
<context>
    <name>contour_axis_diverged</name>
    <message>
        <source>%1 axis: the simulated run diverged (a sample is not a finite number)</source>
        <translation>eixo %1: a simulação divergiu (uma amostra não é um número finito)</translation>
    </message>
</context>
<context>
    <name>contour_axis_saturated</name>
    <message>
        <source>%1 axis: |u| reached the actuator limit of %2 V for %3 s</source>
        <translation>eixo %1: |u| atingiu o limite do atuador de %2 V por %3 s</translation>
    </message>
</context>
<context>
    <name>contour_ballbar_many</name>
    <message>
        <source>the program holds %1 full circles: the figures are those of %2 and %3</source>
        <translation>o programa contém %1 círculos completos: os valores são os de %2 e %3</translation>
    </message>
</context>
<context>
    <name>contour_ballbar_no_opposite</name>
    <message>
        <source>none of the program&apos;s %1 full circles runs the circle of %2 the other way on the same centre and radius: G and F are that circle&apos;s, no circular hysteresis H</source>
        <translation>nenhum dos %1 círculos completos do programa percorre o círculo de %2 no outro sentido com o mesmo centro e raio: G e F são desse círculo, sem histerese circular H</translation>
    </message>
</context>
<context>
    <name>contour_ballbar_one_way</name>
    <message>
        <source>the program runs its full circle (%1) one way only: no circular hysteresis H, which needs a clockwise and a counter-clockwise run of the same circle</source>
        <translation>o programa percorre seu círculo completo (%1) em um só sentido: sem histerese circular H, que precisa de uma execução horária e de uma anti-horária do mesmo círculo</translation>
    </message>
</context>
<context>
    <name>contour_corner_angle</name>
    <message>
        <source>must be in [0, 180) degrees</source>
        <translation>deve estar em [0, 180) graus</translation>
    </message>
</context>
<context>
    <name>contour_feed_per_segment</name>
    <message>
        <source>needs one value per path segment (%1), got %2</source>
        <translation>precisa de um valor por segmento do caminho (%1), recebeu %2</translation>
    </message>
</context>
<context>
    <name>contour_feed_scale_outside</name>
    <message>
        <source>%1 makes the feed of line %2 (%3 mm/s) %4 mm/s, outside the planner&apos;s [%5, %6] mm/s</source>
        <translation>%1 torna o avanço da linha %2 (%3 mm/s) %4 mm/s, fora da faixa [%5, %6] mm/s do planejador</translation>
    </message>
</context>
<context>
    <name>contour_feeds_too_long</name>
    <message>
        <source>every segment at its feed needs at least %1 to move the path&apos;s %5 mm, more than the %2 samples at dt %3 s hold (%4)</source>
        <translation>todos os segmentos em seus avanços precisam de pelo menos %1 para percorrer os %5 mm do caminho, mais do que comportam as %2 amostras com dt %3 s (%4)</translation>
    </message>
</context>
<context>
    <name>contour_fit_radius_not_real</name>
    <message>
        <source>give no circle (the algebraic fit&apos;s radius is not real)</source>
        <translation>não dão nenhum círculo (o raio do ajuste algébrico não é real)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_arc_both_r_ij</name>
    <message>
        <source>arc %1 at column %2 has both R and I/J; give one of them</source>
        <translation>o arco %1 na coluna %2 tem R e I/J; dê apenas um deles</translation>
    </message>
</context>
<context>
    <name>contour_gcode_arc_end_off_circle</name>
    <message>
        <source>arc %1 at column %2: the end point is off the circle (radius %3 mm at the end, %4 mm at the start; tolerance %5 mm)</source>
        <translation>arco %1 na coluna %2: o ponto final está fora do círculo (raio %3 mm no fim, %4 mm no início; tolerância %5 mm)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_arc_needs_centre</name>
    <message>
        <source>arc %1 at column %2 needs I/J (its centre) or R (its radius)</source>
        <translation>o arco %1 na coluna %2 precisa de I/J (seu centro) ou R (seu raio)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_arc_zero_radius</name>
    <message>
        <source>arc %1 at column %2 has a zero radius (I and J are 0)</source>
        <translation>o arco %1 na coluna %2 tem raio nulo (I e J são 0)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_beyond_limit</name>
    <message>
        <source>%1 at column %2 is beyond %3 mm</source>
        <translation>%1 na coluna %2 está além de %3 mm</translation>
    </message>
</context>
<context>
    <name>contour_gcode_block_number</name>
    <message>
        <source>block number %1 at column %2 must be a whole number 0..1e9</source>
        <translation>o número de bloco %1 na coluna %2 deve ser um inteiro 0..1e9</translation>
    </message>
</context>
<context>
    <name>contour_gcode_comment_not_closed</name>
    <message>
        <source>comment opened at column %1 is not closed</source>
        <translation>o comentário aberto na coluna %1 não está fechado</translation>
    </message>
</context>
<context>
    <name>contour_gcode_feed_not_positive</name>
    <message>
        <source>feed %1 at column %2 must be greater than zero</source>
        <translation>o avanço %1 na coluna %2 deve ser maior que zero</translation>
    </message>
</context>
<context>
    <name>contour_gcode_full_circle_r</name>
    <message>
        <source>a full circle needs I and J: R at column %1 leaves its centre undefined</source>
        <translation>um círculo completo precisa de I e J: R na coluna %1 deixa seu centro indefinido</translation>
    </message>
</context>
<context>
    <name>contour_gcode_hex_number</name>
    <message>
        <source>G-code numbers are decimal (no 0x prefix)</source>
        <translation>os números de G-code são decimais (sem prefixo 0x)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_ignored_not_xy</name>
    <message>
        <source>%1 ignored (not an XY motion)</source>
        <translation>%1 ignorado (não é um movimento XY)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_ignored_spindle</name>
    <message>
        <source>%1 ignored (spindle speed)</source>
        <translation>%1 ignorado (velocidade do fuso)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_ignored_tool</name>
    <message>
        <source>%1 ignored (tool)</source>
        <translation>%1 ignorado (ferramenta)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_ignored_z</name>
    <message>
        <source>%1 ignored (the path is XY only)</source>
        <translation>%1 ignorado (o caminho é somente XY)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_incremental_beyond</name>
    <message>
        <source>the incremental move at column %1 ends beyond %2 mm</source>
        <translation>o movimento incremental na coluna %1 termina além de %2 mm</translation>
    </message>
</context>
<context>
    <name>contour_gcode_line</name>
    <message>
        <source>line %1</source>
        <translation>linha %1</translation>
    </message>
</context>
<context>
    <name>contour_gcode_line_warning</name>
    <message>
        <source>line %1: %2</source>
        <translation>linha %1: %2</translation>
    </message>
</context>
<context>
    <name>contour_gcode_lines</name>
    <message>
        <source>lines %1-%2</source>
        <translation>linhas %1-%2</translation>
    </message>
</context>
<context>
    <name>contour_gcode_lines_after_end</name>
    <message>
        <source>the lines after the program end %1 are not read</source>
        <translation>as linhas após o fim de programa %1 não são lidas</translation>
    </message>
</context>
<context>
    <name>contour_gcode_malformed_number</name>
    <message>
        <source>malformed number %1 at column %2: %3</source>
        <translation>número malformado %1 na coluna %2: %3</translation>
    </message>
</context>
<context>
    <name>contour_gcode_more_warnings</name>
    <message>
        <source>... and %1 more warnings</source>
        <translation>... e mais %1 avisos</translation>
    </message>
</context>
<context>
    <name>contour_gcode_needs_arc</name>
    <message>
        <source>%1 at column %2 needs an arc (G2 or G3)</source>
        <translation>%1 na coluna %2 precisa de um arco (G2 ou G3)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_no_feed</name>
    <message>
        <source>feed move %1 at column %2 has no feed rate (no F programmed before it)</source>
        <translation>o movimento de avanço %1 na coluna %2 não tem velocidade de avanço (nenhum F programado antes dele)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_no_feed_modal</name>
    <message>
        <source>feed move at column %1 has no feed rate (no F programmed before it)</source>
        <translation>o movimento de avanço na coluna %1 não tem velocidade de avanço (nenhum F programado antes dele)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_no_motion</name>
    <message>
        <source>has no XY motion (no G0, G1, G2 or G3 move)</source>
        <translation>não tem movimento XY (nenhum movimento G0, G1, G2 ou G3)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_no_motion_mode</name>
    <message>
        <source>%1 at column %2 has no motion mode (G0, G1, G2 or G3) before it</source>
        <translation>%1 na coluna %2 não tem modo de movimento (G0, G1, G2 ou G3) antes dele</translation>
    </message>
</context>
<context>
    <name>contour_gcode_number_not_representable</name>
    <message>
        <source>the number of word %1 at column %2 is not a representable number</source>
        <translation>o número da palavra %1 na coluna %2 não é um número representável</translation>
    </message>
</context>
<context>
    <name>contour_gcode_number_too_long</name>
    <message>
        <source>the number of word %1 at column %2 is longer than %3 characters</source>
        <translation>o número da palavra %1 na coluna %2 tem mais de %3 caracteres</translation>
    </message>
</context>
<context>
    <name>contour_gcode_plane_not_xy</name>
    <message>
        <source>only the XY plane (G17) is supported, not %1 at column %2</source>
        <translation>somente o plano XY (G17) é suportado, não %1 na coluna %2</translation>
    </message>
</context>
<context>
    <name>contour_gcode_radius_below_half_chord</name>
    <message>
        <source>%1 at column %2 is smaller than half the chord (%3 mm) to the end point</source>
        <translation>%1 na coluna %2 é menor que a metade da corda (%3 mm) até o ponto final</translation>
    </message>
</context>
<context>
    <name>contour_gcode_too_many_lines</name>
    <message>
        <source>has more than the limit of %1 lines</source>
        <translation>tem mais que o limite de %1 linhas</translation>
    </message>
</context>
<context>
    <name>contour_gcode_two_decimal_points</name>
    <message>
        <source>more than one decimal point</source>
        <translation>mais de um ponto decimal</translation>
    </message>
</context>
<context>
    <name>contour_gcode_two_distance_modes</name>
    <message>
        <source>two distance modes on one line (%1 at column %2)</source>
        <translation>dois modos de distância em uma linha (%1 na coluna %2)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_two_motion_codes</name>
    <message>
        <source>two motion codes %1 and %2 on one line (at column %3)</source>
        <translation>dois códigos de movimento %1 e %2 em uma linha (na coluna %3)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_two_unit_codes</name>
    <message>
        <source>two unit codes on one line (%1 at column %2)</source>
        <translation>dois códigos de unidade em uma linha (%1 na coluna %2)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_unexpected_character</name>
    <message>
        <source>unexpected character &apos;%1&apos; at column %2</source>
        <translation>caractere inesperado &apos;%1&apos; na coluna %2</translation>
    </message>
</context>
<context>
    <name>contour_gcode_unknown_word</name>
    <message>
        <source>unknown word %1 at column %2</source>
        <translation>palavra desconhecida %1 na coluna %2</translation>
    </message>
</context>
<context>
    <name>contour_gcode_word_no_number</name>
    <message>
        <source>word %1 at column %2 has no number</source>
        <translation>a palavra %1 na coluna %2 não tem número</translation>
    </message>
</context>
<context>
    <name>contour_gcode_word_twice</name>
    <message>
        <source>word %1 is given twice (%2 at column %3)</source>
        <translation>a palavra %1 é dada duas vezes (%2 na coluna %3)</translation>
    </message>
</context>
<context>
    <name>contour_gcode_zero_radius_word</name>
    <message>
        <source>%1 at column %2 is a zero radius</source>
        <translation>%1 na coluna %2 é um raio nulo</translation>
    </message>
</context>
<context>
    <name>contour_has_no_sample</name>
    <message>
        <source>has no sample</source>
        <translation>não tem amostra</translation>
    </message>
</context>
<context>
    <name>contour_has_no_segment</name>
    <message>
        <source>has no segment</source>
        <translation>não tem segmento</translation>
    </message>
</context>
<context>
    <name>contour_jerk_too_long</name>
    <message>
        <source>%5 mm/s^3 needs at least %1 to move the path&apos;s %6 mm from rest to rest (4 (L / 2J)^(1/3)), more than the %2 samples at dt %3 s hold (%4)</source>
        <translation>%5 mm/s^3 precisa de pelo menos %1 para percorrer os %6 mm do caminho de repouso a repouso (4 (L / 2J)^(1/3)), mais do que comportam as %2 amostras com dt %3 s (%4)</translation>
    </message>
</context>
<context>
    <name>contour_line_length_overflows</name>
    <message>
        <source>a line&apos;s length overflows a double</source>
        <translation>o comprimento de uma reta excede a faixa de um double</translation>
    </message>
</context>
<context>
    <name>contour_line_not_finite</name>
    <message>
        <source>a line&apos;s end points must be finite numbers</source>
        <translation>os pontos extremos de uma reta devem ser números finitos</translation>
    </message>
</context>
<context>
    <name>contour_line_zero_length</name>
    <message>
        <source>a line must have a nonzero length</source>
        <translation>uma reta deve ter comprimento não nulo</translation>
    </message>
</context>
<context>
    <name>contour_max_jerk</name>
    <message>
        <source>must be a finite number &gt;= 0 (0: no jerk limit)</source>
        <translation>deve ser um número finito &gt;= 0 (0: sem limite de jerk)</translation>
    </message>
</context>
<context>
    <name>contour_needs_points</name>
    <message>
        <source>needs at least %1 points</source>
        <translation>precisa de pelo menos %1 pontos</translation>
    </message>
</context>
<context>
    <name>contour_one_flag_per_segment</name>
    <message>
        <source>needs one flag per path segment</source>
        <translation>precisa de um indicador por segmento do caminho</translation>
    </message>
</context>
<context>
    <name>contour_path_length_overflows</name>
    <message>
        <source>its length overflows a double</source>
        <translation>seu comprimento excede a faixa de um double</translation>
    </message>
</context>
<context>
    <name>contour_points_collinear</name>
    <message>
        <source>are collinear (or coincide): no circle fits them</source>
        <translation>são colineares (ou coincidem): nenhum círculo se ajusta a eles</translation>
    </message>
</context>
<context>
    <name>contour_profile_too_long</name>
    <message>
        <source>the profile lasts %1 s, %2 samples at dt %3 s, more than the limit of %4</source>
        <translation>o perfil dura %1 s, %2 amostras com dt %3 s, mais que o limite de %4</translation>
    </message>
</context>
<context>
    <name>contour_program_own_feeds_too_long</name>
    <message>
        <source>the program needs at least %1 at its own feeds (the F words), more than the %2 samples at dt %3 s hold (%4)</source>
        <translation>o programa precisa de pelo menos %1 com seus próprios avanços (as palavras F), mais do que comportam as %2 amostras com dt %3 s (%4)</translation>
    </message>
</context>
<context>
    <name>contour_program_scaled_too_long</name>
    <message>
        <source>the program needs at least %1 at %5 times its feeds, more than the %2 samples at dt %3 s hold (%4)</source>
        <translation>o programa precisa de pelo menos %1 com %5 vezes seus avanços, mais do que comportam as %2 amostras com dt %3 s (%4)</translation>
    </message>
</context>
<context>
    <name>contour_rapid_feed_outside</name>
    <message>
        <source>%1 mm/min is outside the planner&apos;s range [%2, %3] mm/min</source>
        <translation>%1 mm/min está fora da faixa [%2, %3] mm/min do planejador</translation>
    </message>
</context>
<context>
    <name>contour_rapid_of_line</name>
    <message>
        <source>%1 (the rapid of line %2)</source>
        <translation>%1 (o movimento rápido da linha %2)</translation>
    </message>
</context>
<context>
    <name>contour_rapids_too_long</name>
    <message>
        <source>running the rapids needs at least %1 at the rapid feed, more than the %2 samples at dt %3 s hold (%4)</source>
        <translation>executar os movimentos rápidos precisa de pelo menos %1 com o avanço rápido, mais do que comportam as %2 amostras com dt %3 s (%4)</translation>
    </message>
</context>
<context>
    <name>contour_rate_outside_range</name>
    <message>
        <source>%1 %2 is outside the planner&apos;s range [%3, %4]</source>
        <translation>%1 %2 está fora da faixa [%3, %4] do planejador</translation>
    </message>
</context>
<context>
    <name>contour_rate_outside_range_or_zero</name>
    <message>
        <source>%1 %2 is outside the planner&apos;s range [%3, %4] (0: none)</source>
        <translation>%1 %2 está fora da faixa [%3, %4] do planejador (0: nenhum)</translation>
    </message>
</context>
<context>
    <name>contour_rate_unit_segment</name>
    <message>
        <source>%1 (segment %2)</source>
        <translation>%1 (segmento %2)</translation>
    </message>
</context>
<context>
    <name>contour_reversal_window</name>
    <message>
        <source>must be in (0, 45] degrees</source>
        <translation>deve estar em (0, 45] graus</translation>
    </message>
</context>
<context>
    <name>contour_segment_feed_invalid</name>
    <message>
        <source>segment %1: must be a finite number &gt; 0, got %2</source>
        <translation>segmento %1: deve ser um número finito &gt; 0, recebeu %2</translation>
    </message>
</context>
<context>
    <name>contour_segment_peak_speed</name>
    <message>
        <source>segment %1 (%2 mm) cannot be planned: its peak speed rounds to %3 mm/s</source>
        <translation>o segmento %1 (%2 mm) não pode ser planejado: sua velocidade de pico arredonda para %3 mm/s</translation>
    </message>
</context>
<context>
    <name>contour_start_within</name>
    <message>
        <source>must be finite and within %1 mm</source>
        <translation>deve ser finito e estar dentro de %1 mm</translation>
    </message>
</context>
<context>
    <name>contour_xy_different_lengths</name>
    <message>
        <source>x and y have different lengths</source>
        <translation>x e y têm comprimentos diferentes</translation>
    </message>
</context>
<context>
    <name>design_a0_normalized</name>
    <message>
        <source>A(0) = %1: A and B divided by it so that A is monic (same plant)</source>
        <translation>A(0) = %1: A e B divididos por ele para que A seja mônico (mesma planta)</translation>
    </message>
</context>
<context>
    <name>design_above_min_frequency</name>
    <message>
        <source>must be above minFrequencyHz</source>
        <translation>deve ser maior que minFrequencyHz</translation>
    </message>
</context>
<context>
    <name>design_b0_not_zero</name>
    <message>
        <source>the z^0 coefficient must be 0 (at least one sample of delay; otherwise u(k) and y(k) form an algebraic loop)</source>
        <translation>o coeficiente de z^0 deve ser 0 (pelo menos uma amostra de atraso; caso contrário u(k) e y(k) formam um laço algébrico)</translation>
    </message>
</context>
<context>
    <name>design_b1_negligible</name>
    <message>
        <source>B(1) = %1 is negligible: the controller (Kf = %2) would need gains beyond 1e100</source>
        <translation>B(1) = %1 é desprezível: o controlador (Kf = %2) precisaria de ganhos acima de 1e100</translation>
    </message>
</context>
<context>
    <name>design_b1_too_small</name>
    <message>
        <source>B(1) = %1 is too small: Kf = T(1)/B(1) overflows a double</source>
        <translation>B(1) = %1 é pequeno demais: Kf = T(1)/B(1) estoura um double</translation>
    </message>
</context>
<context>
    <name>design_b1_zero</name>
    <message>
        <source>B(1) = 0 (a zero at z = 1): the plant has no steady-state gain and Kf = T(1)/B(1) does not exist</source>
        <translation>B(1) = 0 (um zero em z = 1): a planta não tem ganho em regime e Kf = T(1)/B(1) não existe</translation>
    </message>
</context>
<context>
    <name>design_b_zero</name>
    <message>
        <source>B is zero: the plant has no input</source>
        <translation>B é zero: a planta não tem entrada</translation>
    </message>
</context>
<context>
    <name>design_common_factor</name>
    <message>
        <source>shares a root with A (common factor of A and B): A F + B G = T has no solution (Sylvester condition number %1)</source>
        <translation>compartilha uma raiz com A (fator comum de A e B): A F + B G = T não tem solução (número de condição de Sylvester %1)</translation>
    </message>
</context>
<context>
    <name>design_common_factor_root</name>
    <message>
        <source>shares the root z = %1 with A (common factor of A and B): A F + B G = T has no solution (Sylvester condition number %2)</source>
        <translation>compartilha a raiz z = %1 com A (fator comum de A e B): A F + B G = T não tem solução (número de condição de Sylvester %2)</translation>
    </message>
</context>
<context>
    <name>design_coupling_not_negative</name>
    <message>
        <source>must be &gt;= 0 (0 switches the coupling off)</source>
        <translation>deve ser &gt;= 0 (0 desliga o acoplamento)</translation>
    </message>
</context>
<context>
    <name>design_diophantine_overflow</name>
    <message>
        <source>the coefficients of A and B are too large in magnitude: A F + B G overflows a double</source>
        <translation>os coeficientes de A e B são grandes demais em módulo: A F + B G estoura um double</translation>
    </message>
</context>
<context>
    <name>design_gt_k0_out_of_range</name>
    <message>
        <source>plant gain k0 = %1 is out of range with kp = %2 and wn = %3 rad/s: kp k0 = %4, psi1 = wn^4/(kp k0) = %5 and ki = kp psi1 = %6 must be finite nonzero numbers for the Guillemin-Truxal design</source>
        <translation>o ganho da planta k0 = %1 está fora da faixa com kp = %2 e wn = %3 rad/s: kp k0 = %4, psi1 = wn^4/(kp k0) = %5 e ki = kp psi1 = %6 devem ser números finitos não nulos para o projeto de Guillemin-Truxal</translation>
    </message>
</context>
<context>
    <name>design_gt_kp_out_of_range</name>
    <message>
        <source>%1 is out of range with this plant and wn (plant gain k0 = %2, wn = %3 rad/s): kp k0 = %4, psi1 = wn^4/(kp k0) = %5 and ki = kp psi1 = %6 must be finite nonzero numbers for the Guillemin-Truxal design</source>
        <translation>%1 está fora da faixa com esta planta e wn (ganho da planta k0 = %2, wn = %3 rad/s): kp k0 = %4, psi1 = wn^4/(kp k0) = %5 e ki = kp psi1 = %6 devem ser números finitos não nulos para o projeto de Guillemin-Truxal</translation>
    </message>
</context>
<context>
    <name>design_gt_wn_out_of_range</name>
    <message>
        <source>%1 rad/s is out of range: wn^4 = %2 and a2/wn^2 = %3 must be finite nonzero numbers for the reference model (Braga et al. Eq. 11-18)</source>
        <translation>%1 rad/s está fora da faixa: wn^4 = %2 e a2/wn^2 = %3 devem ser números finitos não nulos para o modelo de referência (Braga et al. Eq. 11-18)</translation>
    </message>
</context>
<context>
    <name>design_near_common_factor</name>
    <message>
        <source>near-common factor of A and B; Sylvester condition number %1, F and G are large and sensitive</source>
        <translation>quase fator comum de A e B; número de condição de Sylvester %1, F e G são grandes e sensíveis</translation>
    </message>
</context>
<context>
    <name>design_near_common_factor_pair</name>
    <message>
        <source>near-common factor of A and B: pole z = %1 and zero z = %2 are %3 apart; Sylvester condition number %4, F and G are large and sensitive</source>
        <translation>quase fator comum de A e B: o polo z = %1 e o zero z = %2 estão a %3 de distância; número de condição de Sylvester %4, F e G são grandes e sensíveis</translation>
    </message>
</context>
<context>
    <name>design_no_frequency_to_test</name>
    <message>
        <source>leaves no frequency to test</source>
        <translation>não deixa nenhuma frequência para testar</translation>
    </message>
</context>
<context>
    <name>design_notch_above_nyquist</name>
    <message>
        <source>lies at or above the controller&apos;s Nyquist frequency of %1 Hz (1 / (2 Ts))</source>
        <translation>está na frequência de Nyquist do controlador, %1 Hz (1 / (2 Ts)), ou acima dela</translation>
    </message>
</context>
<context>
    <name>design_notch_centre_range</name>
    <message>
        <source>must be 0 (no notch) or a frequency &gt; 0 Hz</source>
        <translation>deve ser 0 (sem notch) ou uma frequência &gt; 0 Hz</translation>
    </message>
</context>
<context>
    <name>design_notch_depth_range</name>
    <message>
        <source>must be an attenuation in (0, 120] dB</source>
        <translation>deve ser uma atenuação em (0, 120] dB</translation>
    </message>
</context>
<context>
    <name>design_notch_no_mode</name>
    <message>
        <source>the axis has no flexible mode to design a notch for</source>
        <translation>o eixo não tem modo flexível para o qual projetar um filtro notch</translation>
    </message>
</context>
<context>
    <name>design_notch_width_range</name>
    <message>
        <source>must be a bandwidth &gt; 0 Hz and below twice the centre frequency</source>
        <translation>deve ser uma largura de banda &gt; 0 Hz e abaixo do dobro da frequência central</translation>
    </message>
</context>
<context>
    <name>design_pid_conditionally_stable</name>
    <message>
        <source>the closed loop is unstable although the phase margin at the crossover is met (a conditionally stable loop): lower the phase margin or raise the crossover</source>
        <translation>a malha fechada é instável embora a margem de fase no cruzamento seja atendida (uma malha condicionalmente estável): reduza a margem de fase ou aumente a frequência de cruzamento</translation>
    </message>
</context>
<context>
    <name>design_pid_gains_out_of_range</name>
    <message>
        <source>the gains for this target overflow or vanish in double precision (P = %1 V/mm, I = %2 V/(mm s), D = %3 V s/mm) at %4 rad/s (plant phase %5 deg, so the phase margin of %6 deg needs a controller phase of %7 deg)</source>
        <translation>os ganhos para este alvo estouram ou se anulam em precisão dupla (P = %1 V/mm, I = %2 V/(mm s), D = %3 V s/mm) em %4 rad/s (fase da planta %5 graus, então a margem de fase de %6 graus exige uma fase do controlador de %7 graus)</translation>
    </message>
</context>
<context>
    <name>design_pid_phase_out_of_reach</name>
    <message>
        <source>a PID with Ti = 4 Td gives a phase between -90 and 90 deg at %1 rad/s (plant phase %2 deg, so the phase margin of %3 deg needs a controller phase of %4 deg): lower the phase margin or the crossover</source>
        <translation>um PID com Ti = 4 Td dá uma fase entre -90 e 90 graus em %1 rad/s (fase da planta %2 graus, então a margem de fase de %3 graus exige uma fase do controlador de %4 graus): reduza a margem de fase ou a frequência de cruzamento</translation>
    </message>
</context>
<context>
    <name>design_pid_pi_phase_too_high</name>
    <message>
        <source>a PI gives a phase between -90 and 0 deg at %1 rad/s (plant phase %2 deg, so the phase margin of %3 deg needs a controller phase of %4 deg): lower the phase margin or the crossover, or add D</source>
        <translation>um PI dá uma fase entre -90 e 0 graus em %1 rad/s (fase da planta %2 graus, então a margem de fase de %3 graus exige uma fase do controlador de %4 graus): reduza a margem de fase ou a frequência de cruzamento, ou adicione D</translation>
    </message>
</context>
<context>
    <name>design_pid_pi_phase_too_low</name>
    <message>
        <source>a PI gives a phase between -90 and 0 deg at %1 rad/s (plant phase %2 deg, so the phase margin of %3 deg needs a controller phase of %4 deg): raise the crossover or the phase margin</source>
        <translation>um PI dá uma fase entre -90 e 0 graus em %1 rad/s (fase da planta %2 graus, então a margem de fase de %3 graus exige uma fase do controlador de %4 graus): aumente a frequência de cruzamento ou a margem de fase</translation>
    </message>
</context>
<context>
    <name>design_pid_several_crossovers</name>
    <message>
        <source>the loop has %1 gain crossovers (a lightly damped plant, a1^2 &lt; 2 a2): the margin holds at the target, check the others on the Bode plot</source>
        <translation>a malha tem %1 cruzamentos de ganho (uma planta pouco amortecida, a1^2 &lt; 2 a2): a margem vale no alvo, verifique os outros no diagrama de Bode</translation>
    </message>
</context>
<context>
    <name>design_relay_chattering</name>
    <message>
        <source>the relay switched more than 64 times within one step near t = %1 s (chattering): stopped there</source>
        <translation>o relé chaveou mais de 64 vezes em um passo perto de t = %1 s (chattering): parou ali</translation>
    </message>
</context>
<context>
    <name>design_relay_coarse_step</name>
    <message>
        <source>the step of %1 s is coarse against the expected period of %2 s: a step spanning two sign changes of y misses both</source>
        <translation>o passo de %1 s é grosseiro diante do período esperado de %2 s: um passo que abrange duas trocas de sinal de y perde ambas</translation>
    </message>
</context>
<context>
    <name>design_relay_early_crossing</name>
    <message>
        <source>the periodic solution of half period %1 s crosses zero at t = %2 s inside the half period: the relay would switch more often</source>
        <translation>a solução periódica de meio período %1 s cruza o zero em t = %2 s dentro do meio período: o relé chavearia com mais frequência</translation>
    </message>
</context>
<context>
    <name>design_relay_no_half_period</name>
    <message>
        <source>no half period between %1 and %2 s gives a symmetric relay oscillation (y at the switch keeps its sign)</source>
        <translation>nenhum meio período entre %1 e %2 s dá uma oscilação simétrica do relé (y no chaveamento mantém o sinal)</translation>
    </message>
</context>
<context>
    <name>design_relay_not_falling</name>
    <message>
        <source>the periodic solution of half period %1 s does not cross zero downwards at the switch (y&apos; = %2 mm/s): not a relay oscillation</source>
        <translation>a solução periódica de meio período %1 s não cruza o zero descendo no chaveamento (y&apos; = %2 mm/s): não é uma oscilação de relé</translation>
    </message>
</context>
<context>
    <name>design_relay_too_few_switches</name>
    <message>
        <source>fewer than two switches to +d in %1 s: no period or amplitude measured (run longer)</source>
        <translation>menos de dois chaveamentos para +d em %1 s: nenhum período ou amplitude medidos (simule por mais tempo)</translation>
    </message>
</context>
<context>
    <name>design_relay_too_many_steps</name>
    <message>
        <source>%1 s makes %2 steps over %3 s; at most 2e6: raise the step or shorten the run</source>
        <translation>%1 s dá %2 passos em %3 s; no máximo 2e6: aumente o passo ou encurte a simulação</translation>
    </message>
</context>
<context>
    <name>design_spectrum_frequency_order</name>
    <message>
        <source>must be finite, &gt;= 0 and increasing (value %1)</source>
        <translation>deve ser finita, &gt;= 0 e crescente (valor %1)</translation>
    </message>
</context>
<context>
    <name>design_spectrum_no_frequency</name>
    <message>
        <source>has no frequency up to %1 Hz</source>
        <translation>não tem frequência até %1 Hz</translation>
    </message>
</context>
<context>
    <name>design_spectrum_power_negative</name>
    <message>
        <source>must be finite and &gt;= 0 (value %1)</source>
        <translation>deve ser finita e &gt;= 0 (valor %1)</translation>
    </message>
</context>
<context>
    <name>design_spectrum_power_zero</name>
    <message>
        <source>is zero at every frequency used</source>
        <translation>é zero em todas as frequências usadas</translation>
    </message>
</context>
<context>
    <name>design_spectrum_sizes_differ</name>
    <message>
        <source>has %1 values for %2 frequencies</source>
        <translation>tem %1 valores para %2 frequências</translation>
    </message>
</context>
<context>
    <name>design_t0_not_one</name>
    <message>
        <source>T(0), the z^0 coefficient, must be 1</source>
        <translation>T(0), o coeficiente de z^0, deve ser 1</translation>
    </message>
</context>
<context>
    <name>design_t_root_outside</name>
    <message>
        <source>root z = %1 is not inside the unit circle: the closed loop would be unstable</source>
        <translation>a raiz z = %1 não está dentro do círculo unitário: a malha fechada seria instável</translation>
    </message>
</context>
<context>
    <name>design_ti_not_positive</name>
    <message>
        <source>Ti = kp/ki is not a positive time; give Tt (s)</source>
        <translation>Ti = kp/ki não é um tempo positivo; informe Tt (s)</translation>
    </message>
</context>
<context>
    <name>design_tracking_time_not_negative</name>
    <message>
        <source>must be &gt;= 0 (0: Tt = Ti = kp/ki)</source>
        <translation>deve ser &gt;= 0 (0: Tt = Ti = kp/ki)</translation>
    </message>
</context>
<context>
    <name>design_z0_nonzero</name>
    <message>
        <source>the z^0 coefficient must be nonzero</source>
        <translation>o coeficiente de z^0 deve ser diferente de zero</translation>
    </message>
</context>
<context>
    <name>design_zero_polynomial_no_roots</name>
    <message>
        <source>the zero polynomial has no roots</source>
        <translation>o polinômio nulo não tem raízes</translation>
    </message>
</context>
<context>
    <name>design_zpetc_b_minus_out_of_range</name>
    <message>
        <source>B-(1) = %1 is too small (or too large) to square in double precision: scale B, ZPETC cannot normalize its gain</source>
        <translation>B-(1) = %1 é pequeno (ou grande) demais para ser elevado ao quadrado em precisão dupla: escale B, o ZPETC não consegue normalizar seu ganho</translation>
    </message>
</context>
<context>
    <name>design_zpetc_b_minus_zero</name>
    <message>
        <source>B-(1) = 0 (a zero at z = 1): ZPETC cannot normalize the gain</source>
        <translation>B-(1) = 0 (um zero em z = 1): o ZPETC não consegue normalizar o ganho</translation>
    </message>
</context>
<context>
    <name>design_zpetc_overflow</name>
    <message>
        <source>the ZPETC filter overflows in double precision for this B and T: scale B</source>
        <translation>o filtro ZPETC estoura a precisão dupla para estes B e T: escale B</translation>
    </message>
</context>
<context>
    <name>digital_loop_less_damped</name>
    <message>
        <source>the digital loop at Ts = %1 s is much less damped than the design (damping ratio %2 against %3 in the z-plane poles); lower the controller sample time or the delay</source>
        <translation>a malha digital com Ts = %1 s é muito menos amortecida que o projeto (coeficiente de amortecimento %2 contra %3 nos polos do plano z); reduza o período de amostragem do controlador ou o atraso</translation>
    </message>
</context>
<context>
    <name>digital_loop_unstable</name>
    <message>
        <source>the digital loop at Ts = %1 s is unstable (its largest closed-loop pole has |z| = %2); lower the controller sample time</source>
        <translation>a malha digital com Ts = %1 s é instável (seu maior polo de malha fechada tem |z| = %2); reduza o período de amostragem do controlador</translation>
    </message>
</context>
<context>
    <name>feedforward_beyond_limit</name>
    <message>
        <source>the feedforward alone needs %1 V on this trajectory, beyond the output limit of %2 V</source>
        <translation>a pré-alimentação sozinha precisa de %1 V nesta trajetória, além do limite de saída de %2 V</translation>
    </message>
</context>
<context>
    <name>ff3_acceleration_spike</name>
    <message>
        <source>the cubic&apos;s acceleration step becomes a %1 V spike of the FF3 term (one controller period); the quintic move has no acceleration step</source>
        <translation>o degrau de aceleração da cúbica vira um pico de %1 V do termo FF3 (um período do controlador); o movimento quíntico não tem degrau de aceleração</translation>
    </message>
</context>
<context>
    <name>field_reason</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>finite_not_negative</name>
    <message>
        <source>must be a finite number &gt;= 0</source>
        <translation>deve ser um número finito &gt;= 0</translation>
    </message>
</context>
<context>
    <name>finite_positive</name>
    <message>
        <source>must be a finite number greater than zero</source>
        <translation>deve ser um número finito maior que zero</translation>
    </message>
</context>
<context>
    <name>flexible_mode_on_arx</name>
    <message>
        <source>the flexible mode and the notch of gt apply to a continuous plant: this pole-placement axis runs its ARX model, which holds whatever mode its data showed (identify it from a log that excites the mode)</source>
        <translation>o modo flexível e o notch de gt se aplicam a uma planta contínua: este eixo por alocação de polos usa seu modelo ARX, que contém o modo que seus dados mostraram (identifique-o a partir de um registro que excite o modo)</translation>
    </message>
</context>
<context>
    <name>has_no_samples</name>
    <message>
        <source>has no samples</source>
        <translation>não tem amostras</translation>
    </message>
</context>
<context>
    <name>ident_a_sampled_record</name>
    <message>
        <source>a sampled record</source>
        <translation>um registro amostrado</translation>
    </message>
</context>
<context>
    <name>ident_above_log_nyquist</name>
    <message>
        <source>%1 Hz: frequency above the log&apos;s Nyquist frequency of %2 Hz</source>
        <translation>%1 Hz: frequência acima da frequência de Nyquist do log, %2 Hz</translation>
    </message>
</context>
<context>
    <name>ident_accel_beyond</name>
    <message>
        <source>%1 mm/s^2 is beyond %2 mm/s^2 (100 000 g): not an acceleration</source>
        <translation>%1 mm/s^2 está além de %2 mm/s^2 (100 000 g): não é uma aceleração</translation>
    </message>
</context>
<context>
    <name>ident_accel_fields_header</name>
    <message>
        <source>has %1 fields, the header names %2</source>
        <translation>tem %1 campos, o cabeçalho nomeia %2</translation>
    </message>
</context>
<context>
    <name>ident_accel_interval</name>
    <message>
        <source>the sample interval %1 ms differs from the log&apos;s mean %2 ms by more than %3 % (samples lost, or logs joined)</source>
        <translation>o intervalo de amostragem %1 ms difere da média do log, %2 ms, em mais de %3 % (amostras perdidas, ou logs unidos)</translation>
    </message>
</context>
<context>
    <name>ident_accel_klipper_too_few</name>
    <message>
        <source>has %1 samples at %2 Hz: Klipper&apos;s segment of %3 samples (%4 s) needs at least %5 (two half-overlapping segments)</source>
        <translation>tem %1 amostras a %2 Hz: o segmento do Klipper de %3 amostras (%4 s) precisa de pelo menos %5 (dois segmentos com sobreposição de metade)</translation>
    </message>
</context>
<context>
    <name>ident_accel_no_column</name>
    <message>
        <source>no %1 column</source>
        <translation>sem coluna %1</translation>
    </message>
</context>
<context>
    <name>ident_accel_no_header</name>
    <message>
        <source>no header: a Klipper accelerometer log starts with #time,accel_x,accel_y,accel_z</source>
        <translation>sem cabeçalho: um log de acelerômetro do Klipper começa com #time,accel_x,accel_y,accel_z</translation>
    </message>
</context>
<context>
    <name>ident_accel_time_not_after</name>
    <message>
        <source>time %1 s is not after %2 s on line %3</source>
        <translation>o tempo %1 s não é posterior a %2 s da linha %3</translation>
    </message>
</context>
<context>
    <name>ident_accel_times_span</name>
    <message>
        <source>the times span %1 s: no sample interval can be derived</source>
        <translation>os tempos abrangem %1 s: nenhum intervalo de amostragem pode ser derivado</translation>
    </message>
</context>
<context>
    <name>ident_anti_alias_factors</name>
    <message>
        <source>the anti-alias filter is for factors 2 to 1000</source>
        <translation>o filtro anti-aliasing é para fatores de 2 a 1000</translation>
    </message>
</context>
<context>
    <name>ident_arx_input_not_exciting</name>
    <message>
        <source>input not persistently exciting for nb = %1 (the input block has rank %2)</source>
        <translation>entrada não persistentemente excitante para nb = %1 (o bloco da entrada tem posto %2)</translation>
    </message>
</context>
<context>
    <name>ident_arx_regressor_rank</name>
    <message>
        <source>regressor of %1 has rank %2 &lt; %3: the input is not persistently exciting of order na + nb = %4, or the data are exactly of lower order (noise-free): lower na or nb</source>
        <translation>o regressor de %1 tem posto %2 &lt; %3: a entrada não é persistentemente excitante de ordem na + nb = %4, ou os dados são exatamente de ordem menor (sem ruído): reduza na ou nb</translation>
    </message>
</context>
<context>
    <name>ident_arx_unstable</name>
    <message>
        <source>A has a root outside the unit circle: the model is unstable (an integrating axis gives a root near z = 1)</source>
        <translation>A tem uma raiz fora do círculo unitário: o modelo é instável (um eixo integrador dá uma raiz perto de z = 1)</translation>
    </message>
</context>
<context>
    <name>ident_b_all_zeros</name>
    <message>
        <source>is all zeros: the model has no input path</source>
        <translation>é toda nula: o modelo não tem caminho de entrada</translation>
    </message>
</context>
<context>
    <name>ident_band_empty</name>
    <message>
        <source>%1 is empty or reversed</source>
        <translation>%1 está vazia ou invertida</translation>
    </message>
</context>
<context>
    <name>ident_band_few_bins</name>
    <message>
        <source>%1 holds fewer than 3 frequency bins of the estimate (%2 to %3 Hz)</source>
        <translation>%1 contém menos de 3 raias de frequência da estimativa (%2 a %3 Hz)</translation>
    </message>
</context>
<context>
    <name>ident_between_n_100</name>
    <message>
        <source>must be between %1 and 100</source>
        <translation>deve estar entre %1 e 100</translation>
    </message>
</context>
<context>
    <name>ident_beyond_last_sample</name>
    <message>
        <source>is beyond the last sample</source>
        <translation>está além da última amostra</translation>
    </message>
</context>
<context>
    <name>ident_bin_increasing</name>
    <message>
        <source>must be finite and increasing (bin %1)</source>
        <translation>deve ser finito e crescente (raia %1)</translation>
    </message>
</context>
<context>
    <name>ident_bin_not_negative</name>
    <message>
        <source>must be finite and not negative (bin %1)</source>
        <translation>deve ser finito e não negativo (raia %1)</translation>
    </message>
</context>
<context>
    <name>ident_cell_decimal_comma</name>
    <message>
        <source>is not a number (a decimal comma where the file&apos;s decimal separator is the point)</source>
        <translation>não é um número (uma vírgula decimal onde o separador decimal do arquivo é o ponto)</translation>
    </message>
</context>
<context>
    <name>ident_cell_decimal_point</name>
    <message>
        <source>is not a number (a decimal point where the file&apos;s decimal separator is the comma)</source>
        <translation>não é um número (um ponto decimal onde o separador decimal do arquivo é a vírgula)</translation>
    </message>
</context>
<context>
    <name>ident_cell_not_number</name>
    <message>
        <source>is not a number</source>
        <translation>não é um número</translation>
    </message>
</context>
<context>
    <name>ident_cell_out_of_range</name>
    <message>
        <source>is out of the range of a double</source>
        <translation>está fora da faixa de um double</translation>
    </message>
</context>
<context>
    <name>ident_cell_reason</name>
    <message>
        <source>&apos;%1&apos; %2</source>
        <translation>&apos;%1&apos; %2</translation>
    </message>
</context>
<context>
    <name>ident_coefficient_not_finite</name>
    <message>
        <source>has a coefficient that is not finite</source>
        <translation>tem um coeficiente que não é finito</translation>
    </message>
</context>
<context>
    <name>ident_column_input_output</name>
    <message>
        <source>column &apos;%1&apos; is chosen as both input and output</source>
        <translation>a coluna &apos;%1&apos; foi escolhida como entrada e como saída</translation>
    </message>
</context>
<context>
    <name>ident_column_lengths</name>
    <message>
        <source>&apos;%1&apos; has %2 values but &apos;%3&apos; has %4</source>
        <translation>&apos;%1&apos; tem %2 valores, mas &apos;%3&apos; tem %4</translation>
    </message>
</context>
<context>
    <name>ident_column_list_cut</name>
    <message>
        <source>%1, ... (%2 in all)</source>
        <translation>%1, ... (%2 ao todo)</translation>
    </message>
</context>
<context>
    <name>ident_column_name_empty</name>
    <message>
        <source>the column name is empty</source>
        <translation>o nome da coluna está vazio</translation>
    </message>
</context>
<context>
    <name>ident_column_name_twice</name>
    <message>
        <source>the column name &apos;%1&apos; is used twice</source>
        <translation>o nome de coluna &apos;%1&apos; é usado duas vezes</translation>
    </message>
</context>
<context>
    <name>ident_csv_decimal_comma_separator</name>
    <message>
        <source>a decimal comma cannot be read with &apos;,&apos; separating the fields</source>
        <translation>uma vírgula decimal não pode ser lida com &apos;,&apos; separando os campos</translation>
    </message>
</context>
<context>
    <name>ident_csv_header_numbers</name>
    <message>
        <source>holds numbers, not column names: the first line must name the columns</source>
        <translation>contém números, não nomes de colunas: a primeira linha deve nomear as colunas</translation>
    </message>
</context>
<context>
    <name>ident_csv_line_fields</name>
    <message>
        <source>the line has %1 fields but the header names %2</source>
        <translation>a linha tem %1 campos, mas o cabeçalho nomeia %2</translation>
    </message>
</context>
<context>
    <name>ident_csv_no_header</name>
    <message>
        <source>holds no header line (the first line must name the columns)</source>
        <translation>não contém linha de cabeçalho (a primeira linha deve nomear as colunas)</translation>
    </message>
</context>
<context>
    <name>ident_data_u_y_lengths</name>
    <message>
        <source>has %1 samples but data.y has %2</source>
        <translation>tem %1 amostras, mas data.y tem %2</translation>
    </message>
</context>
<context>
    <name>ident_decimation_samples</name>
    <message>
        <source>has %1 samples; decimation needs more than %2</source>
        <translation>tem %1 amostras; a decimação precisa de mais de %2</translation>
    </message>
</context>
<context>
    <name>ident_exceed_parameters</name>
    <message>
        <source>must exceed the number of parameters (%1)</source>
        <translation>deve exceder o número de parâmetros (%1)</translation>
    </message>
</context>
<context>
    <name>ident_excite_clock</name>
    <message>
        <source>the clock period must be 1 to 1000000 samples</source>
        <translation>o período do clock deve ser de 1 a 1000000 amostras</translation>
    </message>
</context>
<context>
    <name>ident_excite_exceeds_umax</name>
    <message>
        <source>|offset| + amplitude = %1 V exceeds umax = %2 V</source>
        <translation>|offset| + amplitude = %1 V excede umax = %2 V</translation>
    </message>
</context>
<context>
    <name>ident_excite_file_extension</name>
    <message>
        <source>the file name must end in .csv or .lvm</source>
        <translation>o nome do arquivo deve terminar em .csv ou .lvm</translation>
    </message>
</context>
<context>
    <name>ident_excite_nyquist</name>
    <message>
        <source>must be from 0 to the Nyquist frequency %1 Hz</source>
        <translation>deve estar entre 0 e a frequência de Nyquist %1 Hz</translation>
    </message>
</context>
<context>
    <name>ident_excite_register</name>
    <message>
        <source>the register length must be 2 to 31</source>
        <translation>o comprimento do registrador deve ser de 2 a 31</translation>
    </message>
</context>
<context>
    <name>ident_excite_shorter_than_ts</name>
    <message>
        <source>is shorter than one sample time</source>
        <translation>é mais curta que um período de amostragem</translation>
    </message>
</context>
<context>
    <name>ident_excite_too_many_samples</name>
    <message>
        <source>gives more than %1 samples at this ts</source>
        <translation>dá mais de %1 amostras com este ts</translation>
    </message>
</context>
<context>
    <name>ident_excite_two_sample_times</name>
    <message>
        <source>must be at least two sample times (%1 s)</source>
        <translation>deve ser de pelo menos dois períodos de amostragem (%1 s)</translation>
    </message>
</context>
<context>
    <name>ident_factor_whole</name>
    <message>
        <source>must be a whole number from 1 to 1000</source>
        <translation>deve ser um número inteiro de 1 a 1000</translation>
    </message>
</context>
<context>
    <name>ident_fewer_samples_than</name>
    <message>
        <source>has %1 samples, fewer than %2</source>
        <translation>tem %1 amostras, menos que %2</translation>
    </message>
</context>
<context>
    <name>ident_finite_gt_zero</name>
    <message>
        <source>must be finite and &gt; 0</source>
        <translation>deve ser finito e &gt; 0</translation>
    </message>
</context>
<context>
    <name>ident_fit_a_not_positive</name>
    <message>
        <source>a1 or a2 is not positive: the fitted plant has a pole in the right half plane or a second integrator</source>
        <translation>a1 ou a2 não é positivo: a planta ajustada tem um polo no semiplano direito ou um segundo integrador</translation>
    </message>
</context>
<context>
    <name>ident_frequency_values_lengths</name>
    <message>
        <source>has %1 values, values %2</source>
        <translation>tem %1 valores, values %2</translation>
    </message>
</context>
<context>
    <name>ident_friction_not_increasing</name>
    <message>
        <source>not strictly increasing at sample %1</source>
        <translation>não é estritamente crescente na amostra %1</translation>
    </message>
</context>
<context>
    <name>ident_friction_not_uniform</name>
    <message>
        <source>not uniformly sampled: step %1 is %2 s, the mean step %3 s</source>
        <translation>não é amostrado uniformemente: o passo %1 é %2 s, o passo médio %3 s</translation>
    </message>
</context>
<context>
    <name>ident_friction_point_velocity_zero</name>
    <message>
        <source>point %1 has velocity 0: no direction</source>
        <translation>o ponto %1 tem velocidade 0: sem sentido</translation>
    </message>
</context>
<context>
    <name>ident_friction_points_directions</name>
    <message>
        <source>%1 points in the + direction and %2 in the - direction: needs at least 2 in each</source>
        <translation>%1 pontos no sentido + e %2 no sentido -: são necessários pelo menos 2 em cada</translation>
    </message>
</context>
<context>
    <name>ident_friction_segments</name>
    <message>
        <source>%1 constant-velocity segments in the + direction and %2 in the - direction: needs jogs in both directions at two or more speeds</source>
        <translation>%1 segmentos de velocidade constante no sentido + e %2 no sentido -: são necessários jogs nos dois sentidos a duas ou mais velocidades</translation>
    </message>
</context>
<context>
    <name>ident_friction_speeds_equal</name>
    <message>
        <source>all speeds are equal: the Coulomb level and the viscous slope cannot be told apart</source>
        <translation>todas as velocidades são iguais: o nível de Coulomb e a inclinação viscosa não podem ser distinguidos</translation>
    </message>
</context>
<context>
    <name>ident_friction_values_for_times</name>
    <message>
        <source>%1 values for %2 times</source>
        <translation>%1 valores para %2 tempos</translation>
    </message>
</context>
<context>
    <name>ident_has_value_not_finite</name>
    <message>
        <source>has a value that is not finite</source>
        <translation>tem um valor que não é finito</translation>
    </message>
</context>
<context>
    <name>ident_holds_no_sample</name>
    <message>
        <source>holds no sample</source>
        <translation>não contém amostra</translation>
    </message>
</context>
<context>
    <name>ident_in_zero_0_1</name>
    <message>
        <source>must be in (0, 0.1]</source>
        <translation>deve estar em (0, 0.1]</translation>
    </message>
</context>
<context>
    <name>ident_input_residuals_lengths</name>
    <message>
        <source>has %1 samples, the residuals %2</source>
        <translation>tem %1 amostras, os resíduos %2</translation>
    </message>
</context>
<context>
    <name>ident_jacobian_rank</name>
    <message>
        <source>the Jacobian has rank %1 &lt; %2: not every parameter is identifiable from these data (no covariance); a lower order may do</source>
        <translation>o jacobiano tem posto %1 &lt; %2: nem todo parâmetro é identificável a partir destes dados (sem covariância); uma ordem menor pode servir</translation>
    </message>
</context>
<context>
    <name>ident_jog_dwell</name>
    <message>
        <source>must be finite and &gt;= 0 (s)</source>
        <translation>deve ser finito e &gt;= 0 (s)</translation>
    </message>
</context>
<context>
    <name>ident_jog_no_speed</name>
    <message>
        <source>give at least one jog speed</source>
        <translation>informe pelo menos uma velocidade de jog</translation>
    </message>
</context>
<context>
    <name>ident_jog_speed_positive</name>
    <message>
        <source>every speed must be finite and &gt; 0 (mm/s), got %1</source>
        <translation>toda velocidade deve ser finita e &gt; 0 (mm/s), recebido %1</translation>
    </message>
</context>
<context>
    <name>ident_jog_too_long</name>
    <message>
        <source>the program lasts %1 s: more than %2 samples at this ts</source>
        <translation>o programa dura %1 s: mais de %2 amostras com este ts</translation>
    </message>
</context>
<context>
    <name>ident_jog_too_many_speeds</name>
    <message>
        <source>%1 speeds: at most %2</source>
        <translation>%1 velocidades: no máximo %2</translation>
    </message>
</context>
<context>
    <name>ident_jog_travel</name>
    <message>
        <source>at %1 mm/s the cruise must last half the move: travel &gt;= 3 V^2 / A = %2 mm</source>
        <translation>a %1 mm/s o cruzeiro deve durar metade do movimento: curso &gt;= 3 V^2 / A = %2 mm</translation>
    </message>
</context>
<context>
    <name>ident_kaiser_beta_range</name>
    <message>
        <source>must be in [0, 50]</source>
        <translation>deve estar em [0, 50]</translation>
    </message>
</context>
<context>
    <name>ident_larger_than_bytes</name>
    <message>
        <source>is larger than %1 bytes</source>
        <translation>é maior que %1 bytes</translation>
    </message>
</context>
<context>
    <name>ident_larger_than_mib</name>
    <message>
        <source>is larger than %1 MiB</source>
        <translation>é maior que %1 MiB</translation>
    </message>
</context>
<context>
    <name>ident_loss_zero</name>
    <message>
        <source>the loss is zero (an exact fit): FPE and AIC are not defined</source>
        <translation>a perda é zero (um ajuste exato): FPE e AIC não são definidos</translation>
    </message>
</context>
<context>
    <name>ident_lvm_bad_decimal_separator</name>
    <message>
        <source>Decimal_Separator &apos;%1&apos; is not &apos;.&apos; or &apos;,&apos;</source>
        <translation>Decimal_Separator &apos;%1&apos; não é &apos;.&apos; nem &apos;,&apos;</translation>
    </message>
</context>
<context>
    <name>ident_lvm_bad_separator</name>
    <message>
        <source>Separator &apos;%1&apos; is not Tab or Comma</source>
        <translation>Separator &apos;%1&apos; não é Tab nem Comma</translation>
    </message>
</context>
<context>
    <name>ident_lvm_bad_x_columns</name>
    <message>
        <source>X_Columns &apos;%1&apos; is not No, One or Multi</source>
        <translation>X_Columns &apos;%1&apos; não é No, One nem Multi</translation>
    </message>
</context>
<context>
    <name>ident_lvm_channel_name_empty</name>
    <message>
        <source>the channel name is empty</source>
        <translation>o nome do canal está vazio</translation>
    </message>
</context>
<context>
    <name>ident_lvm_channel_name_twice</name>
    <message>
        <source>the channel name &apos;%1&apos; is used twice</source>
        <translation>o nome de canal &apos;%1&apos; é usado duas vezes</translation>
    </message>
</context>
<context>
    <name>ident_lvm_decimal_comma_separator</name>
    <message>
        <source>a decimal comma cannot be read with Comma separators</source>
        <translation>uma vírgula decimal não pode ser lida com separadores Comma</translation>
    </message>
</context>
<context>
    <name>ident_lvm_delta_x_contradicts</name>
    <message>
        <source>Delta_X %1 contradicts the X_Value column (field %2), whose mean step from line %3 to line %4 is %5: one of the two is wrong (give the sample time or a time column, after correcting the file)</source>
        <translation>Delta_X %1 contradiz a coluna X_Value (campo %2), cujo passo médio da linha %3 à linha %4 é %5: um dos dois está errado (informe o período de amostragem ou uma coluna de tempo, depois de corrigir o arquivo)</translation>
    </message>
</context>
<context>
    <name>ident_lvm_delta_x_differ</name>
    <message>
        <source>the Delta_X of segment %1 differ between channels or are not positive: no sample time taken from the file</source>
        <translation>os Delta_X do segmento %1 diferem entre canais ou não são positivos: nenhum período de amostragem tomado do arquivo</translation>
    </message>
</context>
<context>
    <name>ident_lvm_header_not_closed</name>
    <message>
        <source>the file header is not closed by ***End_of_Header***</source>
        <translation>o cabeçalho do arquivo não é fechado por ***End_of_Header***</translation>
    </message>
</context>
<context>
    <name>ident_lvm_multi_unpaired</name>
    <message>
        <source>X_Columns is Multi but the name row does not pair every channel with an X_Value column</source>
        <translation>X_Columns é Multi, mas a linha de nomes não pareia cada canal com uma coluna X_Value</translation>
    </message>
</context>
<context>
    <name>ident_lvm_no_name_row</name>
    <message>
        <source>segment %1 has no column-name row: the channels are named Untitled, Untitled 1, ...</source>
        <translation>o segmento %1 não tem linha de nomes de colunas: os canais recebem os nomes Untitled, Untitled 1, ...</translation>
    </message>
</context>
<context>
    <name>ident_lvm_no_segment</name>
    <message>
        <source>holds no data segment</source>
        <translation>não contém segmento de dados</translation>
    </message>
</context>
<context>
    <name>ident_lvm_no_separator_tag</name>
    <message>
        <source>the file header has no Separator tag: Tab assumed</source>
        <translation>o cabeçalho do arquivo não tem a tag Separator: Tab assumido</translation>
    </message>
</context>
<context>
    <name>ident_lvm_no_x_columns_tag</name>
    <message>
        <source>the file header has no X_Columns tag: One assumed</source>
        <translation>o cabeçalho do arquivo não tem a tag X_Columns: One assumido</translation>
    </message>
</context>
<context>
    <name>ident_lvm_not_lvm</name>
    <message>
        <source>is not a LabVIEW Measurement file (the first line must be the tag &apos;LabVIEW Measurement&apos;)</source>
        <translation>não é um arquivo LabVIEW Measurement (a primeira linha deve ser a tag &apos;LabVIEW Measurement&apos;)</translation>
    </message>
</context>
<context>
    <name>ident_lvm_one_segment_not</name>
    <message>
        <source>has %1 segment, not a segment %2</source>
        <translation>tem %1 segmento, não um segmento %2</translation>
    </message>
</context>
<context>
    <name>ident_lvm_row_more_fields</name>
    <message>
        <source>the row has more fields than the column-name row names</source>
        <translation>a linha tem mais campos do que a linha de nomes de colunas nomeia</translation>
    </message>
</context>
<context>
    <name>ident_lvm_second_name_row</name>
    <message>
        <source>a second column-name row in segment %1</source>
        <translation>uma segunda linha de nomes de colunas no segmento %1</translation>
    </message>
</context>
<context>
    <name>ident_lvm_segment_from_one</name>
    <message>
        <source>must be 1 or more (segments are counted from 1)</source>
        <translation>deve ser 1 ou mais (os segmentos são contados a partir de 1)</translation>
    </message>
</context>
<context>
    <name>ident_lvm_segment_header_not_closed</name>
    <message>
        <source>the segment header that starts here with &apos;%1&apos; is not closed by ***End_of_Header***</source>
        <translation>o cabeçalho de segmento que começa aqui com &apos;%1&apos; não é fechado por ***End_of_Header***</translation>
    </message>
</context>
<context>
    <name>ident_lvm_segment_no_channel</name>
    <message>
        <source>segment %1 holds no channel</source>
        <translation>o segmento %1 não contém canal</translation>
    </message>
</context>
<context>
    <name>ident_lvm_segment_read</name>
    <message>
        <source>the file has %1 segments; segment %2 was read</source>
        <translation>o arquivo tem %1 segmentos; o segmento %2 foi lido</translation>
    </message>
</context>
<context>
    <name>ident_lvm_segments_not</name>
    <message>
        <source>has %1 segments, not a segment %2</source>
        <translation>tem %1 segmentos, não um segmento %2</translation>
    </message>
</context>
<context>
    <name>ident_lvm_special_not_closed</name>
    <message>
        <source>the ***Start_Special*** block is not closed by ***End_Special***</source>
        <translation>o bloco ***Start_Special*** não é fechado por ***End_Special***</translation>
    </message>
</context>
<context>
    <name>ident_mat_asked_twice</name>
    <message>
        <source>variable &apos;%1&apos; is asked for twice</source>
        <translation>a variável &apos;%1&apos; é pedida duas vezes</translation>
    </message>
</context>
<context>
    <name>ident_mat_cannot_open</name>
    <message>
        <source>libmatio cannot open it as a MAT file</source>
        <translation>a libmatio não consegue abri-lo como arquivo MAT</translation>
    </message>
</context>
<context>
    <name>ident_mat_cannot_open_why</name>
    <message>
        <source>libmatio cannot open it as a MAT file (%1)</source>
        <translation>a libmatio não consegue abri-lo como arquivo MAT (%1)</translation>
    </message>
</context>
<context>
    <name>ident_mat_cell</name>
    <message>
        <source>is a cell array</source>
        <translation>é um cell array</translation>
    </message>
</context>
<context>
    <name>ident_mat_char</name>
    <message>
        <source>is text (a char array)</source>
        <translation>é texto (um char array)</translation>
    </message>
</context>
<context>
    <name>ident_mat_complex</name>
    <message>
        <source>is complex</source>
        <translation>é complexa</translation>
    </message>
</context>
<context>
    <name>ident_mat_dimensions</name>
    <message>
        <source>has %1 dimensions</source>
        <translation>tem %1 dimensões</translation>
    </message>
</context>
<context>
    <name>ident_mat_element_not_fit</name>
    <message>
        <source>a variable&apos;s element does not fit in the file or has a malformed array header</source>
        <translation>um elemento de variável não cabe no arquivo ou tem um cabeçalho de array malformado</translation>
    </message>
</context>
<context>
    <name>ident_mat_elements</name>
    <message>
        <source>%1 elements</source>
        <translation>%1 elementos</translation>
    </message>
</context>
<context>
    <name>ident_mat_elements_matrix</name>
    <message>
        <source>%1 x %2 elements</source>
        <translation>%1 x %2 elementos</translation>
    </message>
</context>
<context>
    <name>ident_mat_function</name>
    <message>
        <source>is a function handle</source>
        <translation>é um function handle</translation>
    </message>
</context>
<context>
    <name>ident_mat_header_no_variable</name>
    <message>
        <source>it holds a MATLAB header and no variable</source>
        <translation>contém um cabeçalho MATLAB e nenhuma variável</translation>
    </message>
</context>
<context>
    <name>ident_mat_header_version</name>
    <message>
        <source>its MATLAB header states version 0x%1, not 5 (0x0100) or 7.3 (0x0200)</source>
        <translation>seu cabeçalho MATLAB declara a versão 0x%1, não 5 (0x0100) nem 7.3 (0x0200)</translation>
    </message>
</context>
<context>
    <name>ident_mat_logical</name>
    <message>
        <source>is logical (true/false)</source>
        <translation>é lógica (true/false)</translation>
    </message>
</context>
<context>
    <name>ident_mat_matrix</name>
    <message>
        <source>is a %1 x %2 matrix, not a vector</source>
        <translation>é uma matriz %1 x %2, não um vetor</translation>
    </message>
</context>
<context>
    <name>ident_mat_more_not_read</name>
    <message>
        <source>%1 more variables are not read</source>
        <translation>mais %1 variáveis não são lidas</translation>
    </message>
</context>
<context>
    <name>ident_mat_nd_array</name>
    <message>
        <source>is a %1 array (%2 dimensions)</source>
        <translation>é um array %1 (%2 dimensões)</translation>
    </message>
</context>
<context>
    <name>ident_mat_no_header</name>
    <message>
        <source>it starts with neither a MATLAB v5/v7.3 header nor a valid v4 matrix header</source>
        <translation>não começa nem com um cabeçalho MATLAB v5/v7.3 nem com um cabeçalho de matriz v4 válido</translation>
    </message>
</context>
<context>
    <name>ident_mat_no_name</name>
    <message>
        <source>has no name</source>
        <translation>não tem nome</translation>
    </message>
</context>
<context>
    <name>ident_mat_no_variable</name>
    <message>
        <source>has no variable &apos;%1&apos;; %2</source>
        <translation>não tem a variável &apos;%1&apos;; %2</translation>
    </message>
</context>
<context>
    <name>ident_mat_not_mat</name>
    <message>
        <source>is not a MAT file: %1</source>
        <translation>não é um arquivo MAT: %1</translation>
    </message>
</context>
<context>
    <name>ident_mat_not_numeric</name>
    <message>
        <source>variable &apos;%1&apos; is not numeric</source>
        <translation>a variável &apos;%1&apos; não é numérica</translation>
    </message>
</context>
<context>
    <name>ident_mat_not_read</name>
    <message>
        <source>variable &apos;%1&apos; (%2) is not read: %3</source>
        <translation>a variável &apos;%1&apos; (%2) não é lida: %3</translation>
    </message>
</context>
<context>
    <name>ident_mat_not_vector</name>
    <message>
        <source>variable &apos;%1&apos; %2; a vector of real numbers is needed (%3)</source>
        <translation>a variável &apos;%1&apos; %2; é necessário um vetor de números reais (%3)</translation>
    </message>
</context>
<context>
    <name>ident_mat_object</name>
    <message>
        <source>is an object</source>
        <translation>é um objeto</translation>
    </message>
</context>
<context>
    <name>ident_mat_opaque</name>
    <message>
        <source>is an opaque object</source>
        <translation>é um objeto opaco</translation>
    </message>
</context>
<context>
    <name>ident_mat_sparse</name>
    <message>
        <source>is a sparse matrix</source>
        <translation>é uma matriz esparsa</translation>
    </message>
</context>
<context>
    <name>ident_mat_struct</name>
    <message>
        <source>is a struct</source>
        <translation>é uma struct</translation>
    </message>
</context>
<context>
    <name>ident_mat_too_many_asked</name>
    <message>
        <source>%1 variables asked for, more than the %2 a table may hold</source>
        <translation>%1 variáveis pedidas, mais que as %2 que uma tabela pode conter</translation>
    </message>
</context>
<context>
    <name>ident_mat_total_claims</name>
    <message>
        <source>the variables asked for, up to &apos;%1&apos;, hold %2 elements, more than the %3 one read may hold</source>
        <translation>as variáveis pedidas, até &apos;%1&apos;, contêm %2 elementos, mais que os %3 que uma leitura pode conter</translation>
    </message>
</context>
<context>
    <name>ident_mat_unknown_class</name>
    <message>
        <source>is of an unknown class</source>
        <translation>é de uma classe desconhecida</translation>
    </message>
</context>
<context>
    <name>ident_mat_unreadable</name>
    <message>
        <source>the data of variable &apos;%1&apos; cannot be read</source>
        <translation>os dados da variável &apos;%1&apos; não podem ser lidos</translation>
    </message>
</context>
<context>
    <name>ident_mat_unreadable_why</name>
    <message>
        <source>the data of variable &apos;%1&apos; cannot be read (%2)</source>
        <translation>os dados da variável &apos;%1&apos; não podem ser lidos (%2)</translation>
    </message>
</context>
<context>
    <name>ident_mat_usable</name>
    <message>
        <source>the real numeric vectors are: %1</source>
        <translation>os vetores numéricos reais são: %1</translation>
    </message>
</context>
<context>
    <name>ident_mat_usable_none</name>
    <message>
        <source>the real numeric vectors are: (none)</source>
        <translation>os vetores numéricos reais são: (nenhum)</translation>
    </message>
</context>
<context>
    <name>ident_mat_variable_claims</name>
    <message>
        <source>variable &apos;%1&apos; claims %2, more than the %3 one variable may hold</source>
        <translation>a variável &apos;%1&apos; declara %2, mais que os %3 que uma variável pode conter</translation>
    </message>
</context>
<context>
    <name>ident_mat_why_column_limit</name>
    <message>
        <source>a table holds at most %1 variables</source>
        <translation>uma tabela contém no máximo %1 variáveis</translation>
    </message>
</context>
<context>
    <name>ident_mat_why_total_limit</name>
    <message>
        <source>the variables before it already hold %1 of the %2 elements one read may hold</source>
        <translation>as variáveis anteriores já contêm %1 dos %2 elementos que uma leitura pode conter</translation>
    </message>
</context>
<context>
    <name>ident_mat_why_variable_limit</name>
    <message>
        <source>more than the %1 elements one variable may hold</source>
        <translation>mais que os %1 elementos que uma variável pode conter</translation>
    </message>
</context>
<context>
    <name>ident_more_than_columns</name>
    <message>
        <source>has more than %1 columns</source>
        <translation>tem mais de %1 colunas</translation>
    </message>
</context>
<context>
    <name>ident_more_than_fields</name>
    <message>
        <source>has more than %1 fields</source>
        <translation>tem mais de %1 campos</translation>
    </message>
</context>
<context>
    <name>ident_more_than_header_fields</name>
    <message>
        <source>has more than the header&apos;s %1 fields</source>
        <translation>tem mais que os %1 campos do cabeçalho</translation>
    </message>
</context>
<context>
    <name>ident_more_than_names</name>
    <message>
        <source>has more than %1 names</source>
        <translation>tem mais de %1 nomes</translation>
    </message>
</context>
<context>
    <name>ident_needs_two_samples</name>
    <message>
        <source>needs at least 2 samples</source>
        <translation>precisa de pelo menos 2 amostras</translation>
    </message>
</context>
<context>
    <name>ident_nmp_zero</name>
    <message>
        <source>zero outside the unit circle at z = %1 (|z| = %2): non-minimum-phase, its inverse is unstable; this is what makes ZPETC necessary</source>
        <translation>zero fora do círculo unitário em z = %1 (|z| = %2): FNM, sua inversa é instável; é isto que torna o ZPETC necessário</translation>
    </message>
</context>
<context>
    <name>ident_no_column</name>
    <message>
        <source>has no column &apos;%1&apos;; the columns are: %2</source>
        <translation>não tem a coluna &apos;%1&apos;; as colunas são: %2</translation>
    </message>
</context>
<context>
    <name>ident_no_column_none</name>
    <message>
        <source>has no column &apos;%1&apos;; the columns are: (none)</source>
        <translation>não tem a coluna &apos;%1&apos;; as colunas são: (nenhuma)</translation>
    </message>
</context>
<context>
    <name>ident_no_damping_above</name>
    <message>
        <source>no damping: the half-power crossing above the peak at %1 Hz lies outside the band %2</source>
        <translation>sem amortecimento: o cruzamento de meia potência acima do pico em %1 Hz fica fora da banda %2</translation>
    </message>
</context>
<context>
    <name>ident_no_damping_below</name>
    <message>
        <source>no damping: the half-power crossing below the peak at %1 Hz lies outside the band %2</source>
        <translation>sem amortecimento: o cruzamento de meia potência abaixo do pico em %1 Hz fica fora da banda %2</translation>
    </message>
</context>
<context>
    <name>ident_no_stated_sample_time</name>
    <message>
        <source>states no sample time (no Delta_X equal for every channel): give a time column or a sample time</source>
        <translation>não declara período de amostragem (nenhum Delta_X igual para todos os canais): informe uma coluna de tempo ou um período de amostragem</translation>
    </message>
</context>
<context>
    <name>ident_no_time_source</name>
    <message>
        <source>no time source: give a time column or a sample time</source>
        <translation>nenhuma fonte de tempo: informe uma coluna de tempo ou um período de amostragem</translation>
    </message>
</context>
<context>
    <name>ident_noise_std</name>
    <message>
        <source>must be a finite number &gt;= 0 (mm)</source>
        <translation>deve ser um número finito &gt;= 0 (mm)</translation>
    </message>
</context>
<context>
    <name>ident_not_monic</name>
    <message>
        <source>must be monic (first coefficient 1, ascending powers of z^-1)</source>
        <translation>deve ser mônico (primeiro coeficiente 1, potências crescentes de z^-1)</translation>
    </message>
</context>
<context>
    <name>ident_one_sample_needs</name>
    <message>
        <source>has %1 sample; %2 needs at least %3</source>
        <translation>tem %1 amostra; %2 precisa de pelo menos %3</translation>
    </message>
</context>
<context>
    <name>ident_one_time_source</name>
    <message>
        <source>give one time source: a time column, a sample time or the file&apos;s sample time</source>
        <translation>informe uma só fonte de tempo: uma coluna de tempo, um período de amostragem ou o período de amostragem do arquivo</translation>
    </message>
</context>
<context>
    <name>ident_oom</name>
    <message>
        <source>the file needs more memory than is available (%1)</source>
        <translation>o arquivo precisa de mais memória do que a disponível (%1)</translation>
    </message>
</context>
<context>
    <name>ident_oom_file_text</name>
    <message>
        <source>the file&apos;s text</source>
        <translation>o texto do arquivo</translation>
    </message>
</context>
<context>
    <name>ident_oom_its_table</name>
    <message>
        <source>its table</source>
        <translation>a sua tabela</translation>
    </message>
</context>
<context>
    <name>ident_oom_mb_for</name>
    <message>
        <source>%1 MB for %2</source>
        <translation>%1 MB para %2</translation>
    </message>
</context>
<context>
    <name>ident_oom_rows</name>
    <message>
        <source>%1 rows</source>
        <translation>%1 linhas</translation>
    </message>
</context>
<context>
    <name>ident_oom_rows_32_bytes</name>
    <message>
        <source>%1 rows, 32 bytes a row</source>
        <translation>%1 linhas, 32 bytes por linha</translation>
    </message>
</context>
<context>
    <name>ident_oom_rows_of_column</name>
    <message>
        <source>%1 rows of %2 column, 8 bytes a number</source>
        <translation>%1 linhas de %2 coluna, 8 bytes por número</translation>
    </message>
</context>
<context>
    <name>ident_oom_rows_of_columns</name>
    <message>
        <source>%1 rows of %2 columns, 8 bytes a number</source>
        <translation>%1 linhas de %2 colunas, 8 bytes por número</translation>
    </message>
</context>
<context>
    <name>ident_pem_f_unit_circle</name>
    <message>
        <source>F has a root on the unit circle: the model is not asymptotically stable (an integrator in the plant?)</source>
        <translation>F tem uma raiz no círculo unitário: o modelo não é assintoticamente estável (um integrador na planta?)</translation>
    </message>
</context>
<context>
    <name>ident_pem_initial_b</name>
    <message>
        <source>B must have nk + nb = %1 coefficients</source>
        <translation>B deve ter nk + nb = %1 coeficientes</translation>
    </message>
</context>
<context>
    <name>ident_pem_initial_c_d</name>
    <message>
        <source>C and D must be monic with nc + 1 and nd + 1 coefficients</source>
        <translation>C e D devem ser mônicos com nc + 1 e nd + 1 coeficientes</translation>
    </message>
</context>
<context>
    <name>ident_pem_initial_f</name>
    <message>
        <source>F must be monic with nf + 1 coefficients</source>
        <translation>F deve ser mônico com nf + 1 coeficientes</translation>
    </message>
</context>
<context>
    <name>ident_pem_initial_reflected</name>
    <message>
        <source>the initial ARX estimate had an unstable A; its roots were reflected</source>
        <translation>a estimativa ARX inicial tinha um A instável; suas raízes foram refletidas</translation>
    </message>
</context>
<context>
    <name>ident_positive_finite</name>
    <message>
        <source>must be positive and finite</source>
        <translation>deve ser positivo e finito</translation>
    </message>
</context>
<context>
    <name>ident_positive_frequency_hz</name>
    <message>
        <source>must be a positive frequency in Hz</source>
        <translation>deve ser uma frequência positiva em Hz</translation>
    </message>
</context>
<context>
    <name>ident_psd_overflows</name>
    <message>
        <source>is too large: its power spectral density overflows a double</source>
        <translation>é grande demais: sua DEP excede a faixa de um double</translation>
    </message>
</context>
<context>
    <name>ident_quote_not_closed</name>
    <message>
        <source>the quote opened at character %1 is not closed</source>
        <translation>as aspas abertas no caractere %1 não são fechadas</translation>
    </message>
</context>
<context>
    <name>ident_range_min_max</name>
    <message>
        <source>range has min &gt; max</source>
        <translation>o intervalo tem min &gt; max</translation>
    </message>
</context>
<context>
    <name>ident_range_no_sample</name>
    <message>
        <source>no sample lies within [t0, t1]</source>
        <translation>nenhuma amostra está dentro de [t0, t1]</translation>
    </message>
</context>
<context>
    <name>ident_range_reversed</name>
    <message>
        <source>the range ends before it starts (t1 &lt; t0)</source>
        <translation>o intervalo termina antes de começar (t1 &lt; t0)</translation>
    </message>
</context>
<context>
    <name>ident_residuals_need_more</name>
    <message>
        <source>need more than first_sample + max_lag samples</source>
        <translation>precisam de mais de first_sample + max_lag amostras</translation>
    </message>
</context>
<context>
    <name>ident_sample_time_outside</name>
    <message>
        <source>%1 s is outside the accepted sample times, 1e-09 s to 10000 s (no axis experiment is sampled faster or slower, and beyond them a fitted gain underflows to 0 or a session&apos;s run needs more than 1e308 samples)</source>
        <translation>%1 s está fora dos períodos de amostragem aceitos, 1e-09 s a 10000 s (nenhum experimento de eixo é amostrado mais rápido ou mais devagar, e além deles um ganho ajustado cai para 0 por underflow ou uma execução da sessão precisa de mais de 1e308 amostras)</translation>
    </message>
</context>
<context>
    <name>ident_samples_needs</name>
    <message>
        <source>has %1 samples; %2 needs at least %3</source>
        <translation>tem %1 amostras; %2 precisa de pelo menos %3</translation>
    </message>
</context>
<context>
    <name>ident_sampling_zero</name>
    <message>
        <source>the continuous plant has no finite zeros: the zero outside the unit circle is a sampling zero of the ZOH discretization (relative degree 3)</source>
        <translation>a planta contínua não tem zeros finitos: o zero fora do círculo unitário é um zero de amostragem da discretização ZOH (grau relativo 3)</translation>
    </message>
</context>
<context>
    <name>ident_scaled_beyond_double</name>
    <message>
        <source>the value scaled to mm is beyond the range of a double</source>
        <translation>o valor convertido para mm está além da faixa de um double</translation>
    </message>
</context>
<context>
    <name>ident_search_cancelled</name>
    <message>
        <source>cancelled after %1 iterations</source>
        <translation>cancelado após %1 iterações</translation>
    </message>
</context>
<context>
    <name>ident_search_exact_fit</name>
    <message>
        <source>exact fit (the loss is at the round-off level of the data)</source>
        <translation>ajuste exato (a perda está no nível de arredondamento dos dados)</translation>
    </message>
</context>
<context>
    <name>ident_search_gradient_not_finite</name>
    <message>
        <source>the gradient is not finite at an accepted estimate</source>
        <translation>o gradiente não é finito em uma estimativa aceita</translation>
    </message>
</context>
<context>
    <name>ident_search_loss_tolerance</name>
    <message>
        <source>the loss changed by less than the tolerance</source>
        <translation>a perda mudou menos que a tolerância</translation>
    </message>
</context>
<context>
    <name>ident_search_no_damped_step</name>
    <message>
        <source>no damped step lowers the loss: a minimum to working precision</source>
        <translation>nenhum passo amortecido reduz a perda: um mínimo dentro da precisão de trabalho</translation>
    </message>
</context>
<context>
    <name>ident_search_not_finite_initial</name>
    <message>
        <source>the loss or its gradient is not finite at the initial estimate</source>
        <translation>a perda ou seu gradiente não é finito na estimativa inicial</translation>
    </message>
</context>
<context>
    <name>ident_search_step_tolerance</name>
    <message>
        <source>the step was smaller than the tolerance</source>
        <translation>o passo foi menor que a tolerância</translation>
    </message>
</context>
<context>
    <name>ident_search_stopped</name>
    <message>
        <source>stopped at %1 iterations</source>
        <translation>parou em %1 iterações</translation>
    </message>
</context>
<context>
    <name>ident_segment_at_least_4</name>
    <message>
        <source>must be at least 4 samples (got %1)</source>
        <translation>deve ter pelo menos 4 amostras (recebido %1)</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_converged_wrong</name>
    <message>
        <source>Stribeck model not kept: it converged to v_s = %1 mm/s, F_s = %2 V, F_c = %3 V (needs v_s &gt; 0, F_s &gt; F_c)</source>
        <translation>modelo de Stribeck não mantido: convergiu para v_s = %1 mm/s, F_s = %2 V, F_c = %3 V (precisa de v_s &gt; 0, F_s &gt; F_c)</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_few_speeds</name>
    <message>
        <source>Stribeck model not tried: fewer than 3 distinct speeds per direction</source>
        <translation>modelo de Stribeck não tentado: menos de 3 velocidades distintas por sentido</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_line_exact</name>
    <message>
        <source>Stribeck model not tried: the line fits to round-off</source>
        <translation>modelo de Stribeck não tentado: a reta se ajusta até o arredondamento</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_not_allowed</name>
    <message>
        <source>Stribeck model not tried (not allowed)</source>
        <translation>modelo de Stribeck não tentado (não permitido)</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_not_converged</name>
    <message>
        <source>Stribeck model not kept: the search did not converge (MINPACK info %1)</source>
        <translation>modelo de Stribeck não mantido: a busca não convergiu (MINPACK info %1)</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_not_finite</name>
    <message>
        <source>Stribeck model not kept: not finite at the optimum</source>
        <translation>modelo de Stribeck não mantido: não finito no ótimo</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_rank_deficient</name>
    <message>
        <source>Stribeck model not kept: its Jacobian is rank deficient at the optimum</source>
        <translation>modelo de Stribeck não mantido: seu jacobiano tem posto deficiente no ótimo</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_test_kept</name>
    <message>
        <source>%1: Stribeck model kept</source>
        <translation>%1: modelo de Stribeck mantido</translation>
    </message>
</context>
<context>
    <name>ident_stribeck_test_not_kept</name>
    <message>
        <source>%1: Stribeck model not kept</source>
        <translation>%1: modelo de Stribeck não mantido</translation>
    </message>
</context>
<context>
    <name>ident_structure_unknown</name>
    <message>
        <source>&apos;%1&apos; is not arx, oe, bj or gt3</source>
        <translation>&apos;%1&apos; não é arx, oe, bj nem gt3</translation>
    </message>
</context>
<context>
    <name>ident_synthetic_sample_time</name>
    <message>
        <source>the command&apos;s sample time %1 s is not the model&apos;s %2 s</source>
        <translation>o período de amostragem do comando, %1 s, não é o do modelo, %2 s</translation>
    </message>
</context>
<context>
    <name>ident_text_after_quote</name>
    <message>
        <source>text follows the closing quote at character %1</source>
        <translation>há texto após as aspas de fechamento no caractere %1</translation>
    </message>
</context>
<context>
    <name>ident_three_bins</name>
    <message>
        <source>needs at least 3 bins</source>
        <translation>precisa de pelo menos 3 raias</translation>
    </message>
</context>
<context>
    <name>ident_time_lengths</name>
    <message>
        <source>the time &apos;%1&apos; has %2 values but the data %3</source>
        <translation>o tempo &apos;%1&apos; tem %2 valores, mas os dados %3</translation>
    </message>
</context>
<context>
    <name>ident_time_no_sample_time</name>
    <message>
        <source>the time column gives no usable sample time</source>
        <translation>a coluna de tempo não dá um período de amostragem utilizável</translation>
    </message>
</context>
<context>
    <name>ident_time_not_increasing</name>
    <message>
        <source>time %1 s does not increase (the line before holds %2 s)</source>
        <translation>o tempo %1 s não aumenta (a linha anterior contém %2 s)</translation>
    </message>
</context>
<context>
    <name>ident_time_step_differs</name>
    <message>
        <source>the time step %1 s differs from the mean sample time %2 s by more than 1 % (non-uniform sampling)</source>
        <translation>o passo de tempo %1 s difere do período de amostragem médio %2 s em mais de 1 % (amostragem não uniforme)</translation>
    </message>
</context>
<context>
    <name>ident_too_few_samples_for</name>
    <message>
        <source>%1 samples are too few for %2: at least %3 needed</source>
        <translation>%1 amostras são poucas demais para %2: são necessárias pelo menos %3</translation>
    </message>
</context>
<context>
    <name>ident_trend_two_samples</name>
    <message>
        <source>a trend needs at least 2 samples</source>
        <translation>uma tendência precisa de pelo menos 2 amostras</translation>
    </message>
</context>
<context>
    <name>ident_u_y_lengths</name>
    <message>
        <source>u has %1 samples but y has %2</source>
        <translation>u tem %1 amostras, mas y tem %2</translation>
    </message>
</context>
<context>
    <name>ident_validation_sample_time</name>
    <message>
        <source>its sample time %1 s differs from the estimation data&apos;s %2 s</source>
        <translation>seu período de amostragem %1 s difere do dos dados de estimação, %2 s</translation>
    </message>
</context>
<context>
    <name>ident_value_missing</name>
    <message>
        <source>the value is missing</source>
        <translation>o valor está faltando</translation>
    </message>
</context>
<context>
    <name>ident_value_not_finite</name>
    <message>
        <source>value %1 is not finite</source>
        <translation>o valor %1 não é finito</translation>
    </message>
</context>
<context>
    <name>ident_welch_too_few</name>
    <message>
        <source>has %1 samples: fewer than two half-overlapping segments of %2 (at least %3)</source>
        <translation>tem %1 amostras: menos que dois segmentos com sobreposição de metade de %2 (pelo menos %3)</translation>
    </message>
</context>
<context>
    <name>ident_y_u_equally_long</name>
    <message>
        <source>has %1 samples, u has %2: they must be equally long</source>
        <translation>tem %1 amostras, u tem %2: devem ter o mesmo comprimento</translation>
    </message>
</context>
<context>
    <name>ident_yhat_y_lengths</name>
    <message>
        <source>has %1 samples, y has %2</source>
        <translation>tem %1 amostras, y tem %2</translation>
    </message>
</context>
<context>
    <name>ident_zero_phase_samples</name>
    <message>
        <source>zero-phase filtering needs more than %1 samples</source>
        <translation>a filtragem de fase zero precisa de mais de %1 amostras</translation>
    </message>
</context>
<context>
    <name>in_zero_one_open_left</name>
    <message>
        <source>must be in (0, 1]</source>
        <translation>deve estar em (0, 1]</translation>
    </message>
</context>
<context>
    <name>in_zero_one_open_right</name>
    <message>
        <source>must be in [0, 1)</source>
        <translation>deve estar em [0, 1)</translation>
    </message>
</context>
<context>
    <name>io_directory_not_session</name>
    <message>
        <source>is a directory, not a session file</source>
        <translation>é uma pasta, não um arquivo de sessão</translation>
    </message>
</context>
<context>
    <name>io_empty_file_name</name>
    <message>
        <source>the file name is empty</source>
        <translation>o nome do arquivo está vazio</translation>
    </message>
</context>
<context>
    <name>io_foreign_file_in_sticky</name>
    <message>
        <source>is a file of another user (%1) in a folder everyone may write to (sticky); refusing to replace it</source>
        <translation>é um arquivo de outro usuário (%1) em uma pasta em que todos podem escrever (sticky); a substituição é recusada</translation>
    </message>
</context>
<context>
    <name>io_foreign_link_in_sticky</name>
    <message>
        <source>is a symbolic link of another user (%1) in a folder everyone may write to (sticky); refusing to follow it</source>
        <translation>é um link simbólico de outro usuário (%1) em uma pasta em que todos podem escrever (sticky); segui-lo é recusado</translation>
    </message>
</context>
<context>
    <name>io_foreign_link_to_nothing</name>
    <message>
        <source>is a symbolic link of another user (%1) to a file that does not exist; refusing to create it</source>
        <translation>é um link simbólico de outro usuário (%1) para um arquivo que não existe; a criação é recusada</translation>
    </message>
</context>
<context>
    <name>io_is_directory</name>
    <message>
        <source>is a directory</source>
        <translation>é uma pasta</translation>
    </message>
</context>
<context>
    <name>io_larger_than_limit</name>
    <message>
        <source>is larger than the limit of %1 bytes</source>
        <translation>é maior que o limite de %1 bytes</translation>
    </message>
</context>
<context>
    <name>io_link_to_foreign_file</name>
    <message>
        <source>is a symbolic link to a file of another user (the file: %1, the link: %2); refusing to replace it</source>
        <translation>é um link simbólico para um arquivo de outro usuário (o arquivo: %1, o link: %2); a substituição é recusada</translation>
    </message>
</context>
<context>
    <name>io_no_such_file</name>
    <message>
        <source>no such file</source>
        <translation>arquivo inexistente</translation>
    </message>
</context>
<context>
    <name>io_not_regular_file</name>
    <message>
        <source>is not a regular file</source>
        <translation>não é um arquivo comum</translation>
    </message>
</context>
<context>
    <name>io_not_regular_to_read</name>
    <message>
        <source>is not a regular file (a device, FIFO or socket); refusing to read it</source>
        <translation>não é um arquivo comum (um dispositivo, FIFO ou socket); a leitura é recusada</translation>
    </message>
</context>
<context>
    <name>io_not_regular_to_replace</name>
    <message>
        <source>is not a regular file (a device, FIFO or socket); refusing to replace it</source>
        <translation>não é um arquivo comum (um dispositivo, FIFO ou socket); a substituição é recusada</translation>
    </message>
</context>
<context>
    <name>io_size_over_limit</name>
    <message>
        <source>%1 bytes is larger than the limit of %2 bytes</source>
        <translation>%1 bytes é maior que o limite de %2 bytes</translation>
    </message>
</context>
<context>
    <name>is_empty</name>
    <message>
        <source>is empty</source>
        <translation>está vazio</translation>
    </message>
</context>
<context>
    <name>is_missing</name>
    <message>
        <source>is missing</source>
        <translation>está faltando</translation>
    </message>
</context>
<context>
    <name>iso230_circle_too_short</name>
    <message>
        <source>ISO 230-4: a full circle of the program lasts fewer than 3 samples: no figures</source>
        <translation>ISO 230-4: um círculo completo do programa dura menos de 3 amostras: sem valores</translation>
    </message>
</context>
<context>
    <name>limit_cycle_at_rest</name>
    <message>
        <source>a limit cycle at rest: after the move the measured position keeps oscillating (%1 mm peak to peak, %2 turns in the last half of the rest), caused by the encoder/DAC quantization</source>
        <translation>um ciclo-limite em repouso: após o movimento a posição medida continua oscilando (%1 mm pico a pico, %2 inversões na segunda metade do repouso), causado pela quantização do encoder/DAC</translation>
    </message>
</context>
<context>
    <name>list_comma</name>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>list_semicolon</name>
    <message>
        <source>%1; %2</source>
        <translation>%1; %2</translation>
    </message>
</context>
<context>
    <name>model_already_discrete</name>
    <message>
        <source>is already discrete</source>
        <translation>já é discreto</translation>
    </message>
</context>
<context>
    <name>model_anti_resonance_below</name>
    <message>
        <source>must lie below the resonance (a two-mass model&apos;s motor side)</source>
        <translation>deve ficar abaixo da ressonância (o lado do motor de um modelo de duas massas)</translation>
    </message>
</context>
<context>
    <name>model_anti_resonance_frequency</name>
    <message>
        <source>must be 0 (a resonant pair) or a frequency &gt; 0 Hz</source>
        <translation>deve ser 0 (um par ressonante) ou uma frequência &gt; 0 Hz</translation>
    </message>
</context>
<context>
    <name>model_at_least_degree</name>
    <message>
        <source>must be at least the degree %1</source>
        <translation>deve ser pelo menos o grau %1</translation>
    </message>
</context>
<context>
    <name>model_compensation_band</name>
    <message>
        <source>must be a finite number &gt; 0 (mm/s)</source>
        <translation>deve ser um número finito &gt; 0 (mm/s)</translation>
    </message>
</context>
<context>
    <name>model_compensation_percent</name>
    <message>
        <source>must be between 0 and 200 %</source>
        <translation>deve estar entre 0 e 200 %</translation>
    </message>
</context>
<context>
    <name>model_continuous_no_zinv</name>
    <message>
        <source>a continuous system has no z^-1 form</source>
        <translation>um sistema contínuo não tem forma em z^-1</translation>
    </message>
</context>
<context>
    <name>model_damping_ratio</name>
    <message>
        <source>must be a damping ratio in [0, 1)</source>
        <translation>deve ser um coeficiente de amortecimento em [0, 1)</translation>
    </message>
</context>
<context>
    <name>model_denominator_zero</name>
    <message>
        <source>the denominator is zero</source>
        <translation>o denominador é zero</translation>
    </message>
</context>
<context>
    <name>model_different_sample_times</name>
    <message>
        <source>cannot combine systems with different sample times</source>
        <translation>não é possível combinar sistemas com períodos de amostragem diferentes</translation>
    </message>
</context>
<context>
    <name>model_discretization_loses_precision</name>
    <message>
        <source>the exact discretization over %1 s loses double precision (a very fast pole beside a large gain): its step matrix grows by %2 a step where the system grows by %3; use a smaller sample time or rescale the model</source>
        <translation>a discretização exata em %1 s perde a precisão dupla (um polo muito rápido ao lado de um ganho grande): sua matriz de passo cresce %2 por passo onde o sistema cresce %3; use um período de amostragem menor ou reescale o modelo</translation>
    </message>
</context>
<context>
    <name>model_discretization_overflows</name>
    <message>
        <source>the exact discretization over %1 s overflows double precision (a very fast pole): use a smaller sample time</source>
        <translation>a discretização exata em %1 s estoura a precisão dupla (um polo muito rápido): use um período de amostragem menor</translation>
    </message>
</context>
<context>
    <name>model_division_by_zero_polynomial</name>
    <message>
        <source>division by the zero polynomial</source>
        <translation>divisão pelo polinômio nulo</translation>
    </message>
</context>
<context>
    <name>model_empty_coefficient_list</name>
    <message>
        <source>the coefficient list is empty</source>
        <translation>a lista de coeficientes está vazia</translation>
    </message>
</context>
<context>
    <name>model_expected_number</name>
    <message>
        <source>expected a number, got nothing</source>
        <translation>esperava um número, não recebeu nada</translation>
    </message>
</context>
<context>
    <name>model_improper_no_realization</name>
    <message>
        <source>an improper transfer function has no state-space realization</source>
        <translation>uma função de transferência imprópria não tem realização em espaço de estados</translation>
    </message>
</context>
<context>
    <name>model_improper_no_zinv</name>
    <message>
        <source>an improper discrete system has no causal z^-1 form</source>
        <translation>um sistema discreto impróprio não tem forma causal em z^-1</translation>
    </message>
</context>
<context>
    <name>model_mode_frequency</name>
    <message>
        <source>must be 0 (no mode) or a frequency &gt; 0 Hz</source>
        <translation>deve ser 0 (sem modo) ou uma frequência &gt; 0 Hz</translation>
    </message>
</context>
<context>
    <name>model_not_a_finite_number_text</name>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 não é um número finito</translation>
    </message>
</context>
<context>
    <name>model_not_a_number_text</name>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 não é um número</translation>
    </message>
</context>
<context>
    <name>model_number_out_of_range</name>
    <message>
        <source>%1 is out of the range of a double</source>
        <translation>%1 está fora do intervalo de um double</translation>
    </message>
</context>
<context>
    <name>model_root_beyond_double</name>
    <message>
        <source>has a root beyond the range of a double (its leading coefficient is negligible against the others)</source>
        <translation>tem uma raiz além do intervalo de um double (seu coeficiente dominante é desprezível frente aos outros)</translation>
    </message>
</context>
<context>
    <name>model_root_count</name>
    <message>
        <source>has %1 roots, expected %2</source>
        <translation>tem %1 raízes, esperadas %2</translation>
    </message>
</context>
<context>
    <name>model_sample_time</name>
    <message>
        <source>sample time must be a finite number &gt;= 0 (0 for continuous)</source>
        <translation>o período de amostragem deve ser um número finito &gt;= 0 (0 para contínuo)</translation>
    </message>
</context>
<context>
    <name>model_sign</name>
    <message>
        <source>must be +1 or -1</source>
        <translation>deve ser +1 ou -1</translation>
    </message>
</context>
<context>
    <name>model_static_below_coulomb</name>
    <message>
        <source>must be at least the Coulomb level (or 0 for the Coulomb level)</source>
        <translation>deve ser pelo menos o nível de Coulomb (ou 0 para o nível de Coulomb)</translation>
    </message>
</context>
<context>
    <name>model_stribeck_velocity</name>
    <message>
        <source>must be &gt; 0 when the static level is above the Coulomb level</source>
        <translation>deve ser &gt; 0 quando o nível estático está acima do nível de Coulomb</translation>
    </message>
</context>
<context>
    <name>model_too_many_coefficients</name>
    <message>
        <source>more than %1 coefficients</source>
        <translation>mais de %1 coeficientes</translation>
    </message>
</context>
<context>
    <name>model_unclosed_bracket</name>
    <message>
        <source>an opening &apos;[&apos; has no closing &apos;]&apos;</source>
        <translation>um &apos;[&apos; de abertura não tem &apos;]&apos; de fechamento</translation>
    </message>
</context>
<context>
    <name>model_z0_coefficient_zero</name>
    <message>
        <source>the z^0 coefficient of the denominator must be nonzero</source>
        <translation>o coeficiente z^0 do denominador deve ser diferente de zero</translation>
    </message>
</context>
<context>
    <name>model_zero_polynomial_no_leading</name>
    <message>
        <source>the zero polynomial has no leading coefficient</source>
        <translation>o polinômio nulo não tem coeficiente dominante</translation>
    </message>
</context>
<context>
    <name>model_zero_polynomial_no_roots</name>
    <message>
        <source>the zero polynomial has no finite set of roots</source>
        <translation>o polinômio nulo não tem um conjunto finito de raízes</translation>
    </message>
</context>
<context>
    <name>no_digital_implementation</name>
    <message>
        <source>no digital implementation: %1</source>
        <translation>sem implementação digital: %1</translation>
    </message>
</context>
<context>
    <name>no_stability_margins</name>
    <message>
        <source>no stability margins: %1</source>
        <translation>sem margens de estabilidade: %1</translation>
    </message>
</context>
<context>
    <name>not_a_number</name>
    <message>
        <source>must be a number, got NaN</source>
        <translation>deve ser um número, recebido NaN</translation>
    </message>
</context>
<context>
    <name>not_continuous_proper</name>
    <message>
        <source>must be a continuous, proper transfer function</source>
        <translation>deve ser uma função de transferência contínua e própria</translation>
    </message>
</context>
<context>
    <name>not_continuous_strictly_proper</name>
    <message>
        <source>must be a continuous, strictly proper transfer function</source>
        <translation>deve ser uma função de transferência contínua e estritamente própria</translation>
    </message>
</context>
<context>
    <name>not_finite</name>
    <message>
        <source>must be finite, got infinity</source>
        <translation>deve ser finito, recebido infinito</translation>
    </message>
</context>
<context>
    <name>not_finite_value</name>
    <message>
        <source>is NaN or infinite</source>
        <translation>é NaN ou infinito</translation>
    </message>
</context>
<context>
    <name>not_negative</name>
    <message>
        <source>must be &gt;= 0</source>
        <translation>deve ser &gt;= 0</translation>
    </message>
</context>
<context>
    <name>not_positive</name>
    <message>
        <source>must be greater than zero</source>
        <translation>deve ser maior que zero</translation>
    </message>
</context>
<context>
    <name>point_not_finite</name>
    <message>
        <source>point %1 is not finite</source>
        <translation>o ponto %1 não é finito</translation>
    </message>
</context>
<context>
    <name>pp_u_exceeds_limit</name>
    <message>
        <source>|u| exceeds the actuator limit (the discrete loop is simulated without saturation)</source>
        <translation>|u| excede o limite do atuador (a malha discreta é simulada sem saturação)</translation>
    </message>
</context>
<context>
    <name>reversal_spikes</name>
    <message>
        <source>reversal spikes up to %1 mm at the quadrant changes (the table&apos;s friction and backlash)</source>
        <translation>picos de reversão de até %1 mm nas mudanças de quadrante (o atrito e a folga da mesa)</translation>
    </message>
</context>
<context>
    <name>run_diverged</name>
    <message>
        <source>the simulated run diverged (a sample is not a finite number): it has no tracking figures</source>
        <translation>a simulação divergiu (uma amostra não é um número finito): não há valores de seguimento</translation>
    </message>
</context>
<context>
    <name>run_ends_before_move</name>
    <message>
        <source>the run ends before the move does (tf): no settle figures</source>
        <translation>a simulação termina antes do movimento (tf): sem valores de acomodação</translation>
    </message>
</context>
<context>
    <name>sample_not_finite</name>
    <message>
        <source>sample %1 is not finite</source>
        <translation>a amostra %1 não é finita</translation>
    </message>
</context>
<context>
    <name>session_advice_axis</name>
    <message>
        <source>axis %1</source>
        <translation>eixo %1</translation>
    </message>
</context>
<context>
    <name>session_advice_change</name>
    <message>
        <source>%1 %2 %3</source>
        <translation>%1 %2 %3</translation>
    </message>
</context>
<context>
    <name>session_advice_gain_margin</name>
    <message>
        <source>%1: gain margin %2 dB (minimum %3)</source>
        <translation>%1: margem de ganho %2 dB (mínimo %3)</translation>
    </message>
</context>
<context>
    <name>session_advice_no_design</name>
    <message>
        <source>%1 has no design (%2: %3)</source>
        <translation>%1 não tem projeto (%2: %3)</translation>
    </message>
</context>
<context>
    <name>session_advice_overshoot</name>
    <message>
        <source>%1: the step overshoots %2 % (limit %3 %)</source>
        <translation>%1: o degrau tem sobressinal de %2 % (limite %3 %)</translation>
    </message>
</context>
<context>
    <name>session_advice_overshoot_gt</name>
    <message>
        <source>%1: the step overshoots %2 % (limit %3 %): every Guillemin-Truxal design overshoots, its reference model is type 2 (the step error integrates to zero), so 0 % cannot be met</source>
        <translation>%1: o degrau tem sobressinal de %2 % (limite %3 %): todo projeto Guillemin-Truxal tem sobressinal, seu modelo de referência é de tipo 2 (o erro ao degrau integra a zero), então 0 % não pode ser atendido</translation>
    </message>
</context>
<context>
    <name>session_advice_phase_margin</name>
    <message>
        <source>%1: phase margin %2 deg (minimum %3)</source>
        <translation>%1: margem de fase %2 deg (mínimo %3)</translation>
    </message>
</context>
<context>
    <name>session_advice_saturation</name>
    <message>
        <source>%1: the command reaches the ±%2 V limit; a looser limit elsewhere does not change that</source>
        <translation>%1: o comando atinge o limite de ±%2 V; um limite mais folgado em outro lugar não muda isso</translation>
    </message>
</context>
<context>
    <name>session_advice_settle_after</name>
    <message>
        <source>%1: it settles into ±%2 mm only %3 s after the move (limit %4 s)</source>
        <translation>%1: acomoda-se em ±%2 mm só %3 s após o movimento (limite %4 s)</translation>
    </message>
</context>
<context>
    <name>session_advice_settle_estimated</name>
    <message>
        <source>%1: it settles into ±%2 mm only about %3 s after the move (estimated: not within the run) (limit %4 s)</source>
        <translation>%1: acomoda-se em ±%2 mm só cerca de %3 s após o movimento (estimado: não dentro da execução) (limite %4 s)</translation>
    </message>
</context>
<context>
    <name>session_advice_settle_not_within</name>
    <message>
        <source>%1: it settles into ±%2 mm not within the run (limit %3 s)</source>
        <translation>%1: não se acomoda em ±%2 mm dentro da execução (limite %3 s)</translation>
    </message>
</context>
<context>
    <name>session_advice_settling</name>
    <message>
        <source>%1: the step settles in %2 s (limit %3 s)</source>
        <translation>%1: o degrau se acomoda em %2 s (limite %3 s)</translation>
    </message>
</context>
<context>
    <name>session_advice_slowest_pole</name>
    <message>
        <source>%1: its slowest closed-loop pole, at -%2 rad/s beside the PI zero, decays that slowly</source>
        <translation>%1: seu polo de malha fechada mais lento, em -%2 rad/s ao lado do zero do PI, decai assim devagar</translation>
    </message>
</context>
<context>
    <name>session_advice_tracking</name>
    <message>
        <source>%1: the tracking error reaches %2 % of the travel (limit %3 %)</source>
        <translation>%1: o erro de seguimento atinge %2 % do curso (limite %3 %)</translation>
    </message>
</context>
<context>
    <name>session_advice_unstable</name>
    <message>
        <source>%1: the closed loop is unstable; no limit makes it pass</source>
        <translation>%1: a malha fechada é instável; nenhum limite a faz passar</translation>
    </message>
</context>
<context>
    <name>session_arx_backlash</name>
    <message>
        <source>backlash needs the moving mass of a continuous plant; a pole-placement axis&apos; ARX model takes the Coulomb level and the amplifier deadband only, as a dead zone of its input</source>
        <translation>a folga precisa da massa móvel de uma planta contínua; o modelo ARX de um eixo de alocação de polos aceita apenas o nível de Coulomb e a zona morta do amplificador, como uma zona morta da sua entrada</translation>
    </message>
</context>
<context>
    <name>session_arx_compensation</name>
    <message>
        <source>friction compensation needs the moving mass of a continuous plant; a pole-placement axis&apos; ARX model takes the Coulomb level and the amplifier deadband only, as a dead zone of its input</source>
        <translation>a compensação de atrito precisa da massa móvel de uma planta contínua; o modelo ARX de um eixo de alocação de polos aceita apenas o nível de Coulomb e a zona morta do amplificador, como uma zona morta da sua entrada</translation>
    </message>
</context>
<context>
    <name>session_arx_static_level</name>
    <message>
        <source>a static level above the Coulomb level needs the moving mass of a continuous plant; a pole-placement axis&apos; ARX model takes the Coulomb level and the amplifier deadband only, as a dead zone of its input</source>
        <translation>um nível estático acima do nível de Coulomb precisa da massa móvel de uma planta contínua; o modelo ARX de um eixo de alocação de polos aceita apenas o nível de Coulomb e a zona morta do amplificador, como uma zona morta da sua entrada</translation>
    </message>
</context>
<context>
    <name>session_arx_viscous</name>
    <message>
        <source>viscous friction needs the moving mass of a continuous plant; a pole-placement axis&apos; ARX model takes the Coulomb level and the amplifier deadband only, as a dead zone of its input</source>
        <translation>o atrito viscoso precisa da massa móvel de uma planta contínua; o modelo ARX de um eixo de alocação de polos aceita apenas o nível de Coulomb e a zona morta do amplificador, como uma zona morta da sua entrada</translation>
    </message>
</context>
<context>
    <name>session_axis_id_not_unique</name>
    <message>
        <source>must differ from axes[0].id</source>
        <translation>deve ser diferente de axes[0].id</translation>
    </message>
</context>
<context>
    <name>session_axis_no_design</name>
    <message>
        <source>has no design</source>
        <translation>não tem projeto</translation>
    </message>
</context>
<context>
    <name>session_axis_no_digital_to_couple</name>
    <message>
        <source>axis %1 has no digital implementation to couple</source>
        <translation>o eixo %1 não tem implementação digital para acoplar</translation>
    </message>
</context>
<context>
    <name>session_bad_axis_id</name>
    <message>
        <source>must be 1 to 16 lower-case letters or digits (it names the exported C functions)</source>
        <translation>deve ter de 1 a 16 letras minúsculas ou dígitos (nomeia as funções C exportadas)</translation>
    </message>
</context>
<context>
    <name>session_bad_method_id</name>
    <message>
        <source>the id &apos;%1&apos; must be 1 to 32 lower-case letters, digits, &apos;-&apos; or &apos;_&apos;</source>
        <translation>o id &apos;%1&apos; deve ter de 1 a 32 letras minúsculas, dígitos, &apos;-&apos; ou &apos;_&apos;</translation>
    </message>
</context>
<context>
    <name>session_bad_method_parameter</name>
    <message>
        <source>the parameter &apos;%1&apos; of &apos;%2&apos; needs a name of lower-case letters, digits and &apos;_&apos; and minimum &lt;= default &lt;= maximum</source>
        <translation>o parâmetro &apos;%1&apos; de &apos;%2&apos; precisa de um nome de letras minúsculas, dígitos e &apos;_&apos; e mínimo &lt;= padrão &lt;= máximo</translation>
    </message>
</context>
<context>
    <name>session_cannot_export</name>
    <message>
        <source>cannot be exported: %1: %2</source>
        <translation>não pode ser exportado: %1: %2</translation>
    </message>
</context>
<context>
    <name>session_cannot_run</name>
    <message>
        <source>cannot run: %1: %2</source>
        <translation>não pode executar: %1: %2</translation>
    </message>
</context>
<context>
    <name>session_contour_needs_path</name>
    <message>
        <source>the contour analysis needs a circle or a G-code program (a cubic drives both axes along one line)</source>
        <translation>a análise de contorno precisa de um círculo ou de um programa G-code (uma cúbica move os dois eixos ao longo de uma reta)</translation>
    </message>
</context>
<context>
    <name>session_controller_continuous</name>
    <message>
        <source>must be continuous (a discrete loop has its own model)</source>
        <translation>deve ser contínuo (uma malha discreta tem seu próprio modelo)</translation>
    </message>
</context>
<context>
    <name>session_coupled_loop_unstable</name>
    <message>
        <source>the coupled loop is unstable on %1 (direction %2): spectral radius %3; lower the coupling&apos;s gains (kp %4 V/mm, ki %5 V/(mm s))</source>
        <translation>a malha acoplada é instável em %1 (direção %2): raio espectral %3; reduza os ganhos do acoplamento (kp %4 V/mm, ki %5 V/(mm s))</translation>
    </message>
</context>
<context>
    <name>session_coupled_run_diverged</name>
    <message>
        <source>the coupled run diverged (its contour error is not a finite number)</source>
        <translation>a execução acoplada divergiu (seu erro de contorno não é um número finito)</translation>
    </message>
</context>
<context>
    <name>session_coupled_run_diverged_because</name>
    <message>
        <source>the coupled run diverged (%1)</source>
        <translation>a execução acoplada divergiu (%1)</translation>
    </message>
</context>
<context>
    <name>session_coupling_frozen_unstable</name>
    <message>
        <source>the coupled loop frozen at %1 of %2 directions is unstable (spectral radius up to %3 at %4): on the arcs the coupling may not settle</source>
        <translation>a malha acoplada congelada em %1 de %2 direções é instável (raio espectral até %3 em %4): nos arcos o acoplamento pode não se acomodar</translation>
    </message>
</context>
<context>
    <name>session_coupling_off</name>
    <message>
        <source>is off (kp and ki are 0)</source>
        <translation>está desligado (kp e ki são 0)</translation>
    </message>
</context>
<context>
    <name>session_coupling_one_digital_period</name>
    <message>
        <source>needs both digital controllers at one period: the x axis runs every %1 s, the y axis every %2 s</source>
        <translation>precisa dos dois controladores digitais com um só período: o eixo x executa a cada %1 s, o eixo y a cada %2 s</translation>
    </message>
</context>
<context>
    <name>session_coupling_one_period_why</name>
    <message>
        <source>needs both axes at one controller period: the x axis runs every %1 s, the y axis every %2 s (a pole-placement axis runs at its Ts, a continuous one at the trajectory&apos;s dt)</source>
        <translation>precisa dos dois eixos com um só período de controlador: o eixo x executa a cada %1 s, o eixo y a cada %2 s (um eixo de alocação de polos executa no seu Ts, um contínuo no dt da trajetória)</translation>
    </message>
</context>
<context>
    <name>session_criterion_actuator_limit</name>
    <message>
        <source>the actuator limit</source>
        <translation>o limite do atuador</translation>
    </message>
</context>
<context>
    <name>session_criterion_settle</name>
    <message>
        <source>the settle after the move</source>
        <translation>a acomodação após o movimento</translation>
    </message>
</context>
<context>
    <name>session_criterion_tracking_error</name>
    <message>
        <source>the tracking error</source>
        <translation>o erro de seguimento</translation>
    </message>
</context>
<context>
    <name>session_cross_coupling_note</name>
    <message>
        <source>cross-coupling: %1</source>
        <translation>acoplamento cruzado: %1</translation>
    </message>
</context>
<context>
    <name>session_derivative_filter_beyond_nyquist</name>
    <message>
        <source>%1 s puts the filter&apos;s corner 1/Tf beyond the Nyquist frequency pi/Ts of the controller period: use 0 (no filter) or at least %2 s</source>
        <translation>%1 s coloca a frequência de corte 1/Tf do filtro além da frequência de Nyquist pi/Ts do período do controlador: use 0 (sem filtro) ou pelo menos %2 s</translation>
    </message>
</context>
<context>
    <name>session_design_space_methods</name>
    <message>
        <source>the design space applies to Guillemin-Truxal and PI + feedforward axes</source>
        <translation>o espaço de projeto se aplica a eixos Guillemin-Truxal e PI + pré-alimentação</translation>
    </message>
</context>
<context>
    <name>session_design_space_pi_only</name>
    <message>
        <source>the design space maps PI gains (with the feedforward): set D to 0</source>
        <translation>o espaço de projeto mapeia ganhos PI (com a pré-alimentação): ajuste D para 0</translation>
    </message>
</context>
<context>
    <name>session_digital_runs_samples</name>
    <message>
        <source>the two digital runs do not have the same samples</source>
        <translation>as duas execuções digitais não têm as mesmas amostras</translation>
    </message>
</context>
<context>
    <name>session_duration_circle</name>
    <message>
        <source>duration %1 s (automatic: the ramp-in and one revolution)</source>
        <translation>duração %1 s (automática: a rampa de entrada e uma volta)</translation>
    </message>
</context>
<context>
    <name>session_duration_move_only</name>
    <message>
        <source>duration %1 s (automatic: the move only; no axis has a stable design to settle)</source>
        <translation>duração %1 s (automática: só o movimento; nenhum eixo tem projeto estável para se acomodar)</translation>
    </message>
</context>
<context>
    <name>session_duration_never</name>
    <message>
        <source>never</source>
        <translation>nunca</translation>
    </message>
</context>
<context>
    <name>session_duration_program</name>
    <message>
        <source>duration %1 s (the program&apos;s feed profile)</source>
        <translation>duração %1 s (o perfil de avanço do programa)</translation>
    </message>
</context>
<context>
    <name>session_duration_set</name>
    <message>
        <source>duration %1 s (set in the session)</source>
        <translation>duração %1 s (definida na sessão)</translation>
    </message>
</context>
<context>
    <name>session_duration_settle</name>
    <message>
        <source>duration %1 s (automatic: the move to tf = %2 s and the settle into %3 mm, estimated %4 after tf from the slowest closed-loop pole)</source>
        <translation>duração %1 s (automática: o movimento até tf = %2 s e a acomodação em %3 mm, estimada %4 após tf pelo polo de malha fechada mais lento)</translation>
    </message>
</context>
<context>
    <name>session_duration_settle_capped</name>
    <message>
        <source>duration %1 s (automatic: the move to tf = %2 s and the settle into %3 mm, estimated %4 after tf from the slowest closed-loop pole; cut to the cap of tf + %5 move durations)</source>
        <translation>duração %1 s (automática: o movimento até tf = %2 s e a acomodação em %3 mm, estimada %4 após tf pelo polo de malha fechada mais lento; cortada no teto de tf + %5 durações do movimento)</translation>
    </message>
</context>
<context>
    <name>session_duration_settle_lowered</name>
    <message>
        <source>duration %1 s (automatic: the move to tf = %2 s and the settle into %3 mm, estimated %4 after tf from the slowest closed-loop pole; cut to the cap of tf + %5 move durations (lowered to what a million samples hold at this dt))</source>
        <translation>duração %1 s (automática: o movimento até tf = %2 s e a acomodação em %3 mm, estimada %4 após tf pelo polo de malha fechada mais lento; cortada no teto de tf + %5 durações do movimento (reduzido ao que um milhão de amostras comporta neste dt))</translation>
    </message>
</context>
<context>
    <name>session_export_not_finite</name>
    <message>
        <source>gives %1 in the export, not a finite number; nothing was exported</source>
        <translation>dá %1 na exportação, não um número finito; nada foi exportado</translation>
    </message>
</context>
<context>
    <name>session_float_overflow</name>
    <message>
        <source>gives %1 for %2, beyond the largest float (%3): it would be inf in float arithmetic; export in double precision; nothing was exported</source>
        <translation>dá %1 para %2, além do maior float (%3): seria inf em aritmética float; exporte em precisão dupla; nada foi exportado</translation>
    </message>
</context>
<context>
    <name>session_float_underflow</name>
    <message>
        <source>gives %1 for %2, which rounds to 0 in float (the smallest is %3); export in double precision; nothing was exported</source>
        <translation>dá %1 para %2, que arredonda para 0 em float (o menor é %3); exporte em precisão dupla; nada foi exportado</translation>
    </message>
</context>
<context>
    <name>session_identified_no_covariance</name>
    <message>
        <source>the identified %1 has no covariance to draw plants from</source>
        <translation>o %1 identificado não tem covariância para sortear plantas</translation>
    </message>
</context>
<context>
    <name>session_identified_wrong_method</name>
    <message>
        <source>the identified %1 is not a model of the axis&apos; design method</source>
        <translation>o %1 identificado não é um modelo do método de projeto do eixo</translation>
    </message>
</context>
<context>
    <name>session_implementation_fails</name>
    <message>
        <source>the design meets %1, its digital implementation does not: the verdict is the implementation&apos;s</source>
        <translation>o projeto atende %1, sua implementação digital não: o veredito é o da implementação</translation>
    </message>
</context>
<context>
    <name>session_iso230_note</name>
    <message>
        <source>ISO 230-4: %1</source>
        <translation>ISO 230-4: %1</translation>
    </message>
</context>
<context>
    <name>session_limit_in_position_window</name>
    <message>
        <source>in-position window</source>
        <translation>janela de posição</translation>
    </message>
</context>
<context>
    <name>session_limit_max_error</name>
    <message>
        <source>max error</source>
        <translation>erro máx.</translation>
    </message>
</context>
<context>
    <name>session_limit_max_overshoot</name>
    <message>
        <source>max overshoot</source>
        <translation>sobressinal máx.</translation>
    </message>
</context>
<context>
    <name>session_limit_max_settle_time</name>
    <message>
        <source>max settle time</source>
        <translation>tempo de acomodação após o movimento máx.</translation>
    </message>
</context>
<context>
    <name>session_limit_max_settling_time</name>
    <message>
        <source>max settling time</source>
        <translation>tempo de acomodação máx.</translation>
    </message>
</context>
<context>
    <name>session_limit_min_gain_margin</name>
    <message>
        <source>min gain margin</source>
        <translation>margem de ganho mín.</translation>
    </message>
</context>
<context>
    <name>session_limit_min_phase_margin</name>
    <message>
        <source>min phase margin</source>
        <translation>margem de fase mín.</translation>
    </message>
</context>
<context>
    <name>session_list_and</name>
    <message>
        <source>%1 and %2</source>
        <translation>%1 e %2</translation>
    </message>
</context>
<context>
    <name>session_max_samples</name>
    <message>
        <source>a run needs at least 2 samples (0: no limit)</source>
        <translation>uma execução precisa de pelo menos 2 amostras (0: sem limite)</translation>
    </message>
</context>
<context>
    <name>session_method_not_registered</name>
    <message>
        <source>no design method is registered for this value</source>
        <translation>nenhum método de projeto está registrado para este valor</translation>
    </message>
</context>
<context>
    <name>session_method_registered</name>
    <message>
        <source>a method with the value or the id of &apos;%1&apos; is registered already</source>
        <translation>um método com o valor ou o id de &apos;%1&apos; já está registrado</translation>
    </message>
</context>
<context>
    <name>session_method_takes_no_coupling</name>
    <message>
        <source>the %1 method&apos;s loop takes no coupling</source>
        <translation>a malha do método %1 não aceita acoplamento</translation>
    </message>
</context>
<context>
    <name>session_mode_and_friction</name>
    <message>
        <source>a flexible mode and the table&apos;s friction are not simulated together (the friction model&apos;s moving mass is rigid): set the mode&apos;s frequency or the friction levels to 0</source>
        <translation>um modo flexível e o atrito da mesa não são simulados juntos (a massa móvel do modelo de atrito é rígida): ajuste a frequência do modo ou os níveis de atrito para 0</translation>
    </message>
</context>
<context>
    <name>session_model_no_estimate</name>
    <message>
        <source>%1 has no estimate (%2)</source>
        <translation>%1 não tem estimativa (%2)</translation>
    </message>
</context>
<context>
    <name>session_model_no_estimate_because</name>
    <message>
        <source>%1 has no estimate (%2: %3)</source>
        <translation>%1 não tem estimativa (%2: %3)</translation>
    </message>
</context>
<context>
    <name>session_model_not_identified</name>
    <message>
        <source>the axis&apos; model was not identified from data (set ranges instead)</source>
        <translation>o modelo do eixo não foi identificado a partir de dados (defina faixas em vez disso)</translation>
    </message>
</context>
<context>
    <name>session_needs_one_value</name>
    <message>
        <source>needs at least one value</source>
        <translation>precisa de pelo menos um valor</translation>
    </message>
</context>
<context>
    <name>session_no_axis</name>
    <message>
        <source>there is no axis %1</source>
        <translation>não há eixo %1</translation>
    </message>
</context>
<context>
    <name>session_no_digital_controller</name>
    <message>
        <source>this axis has no digital controller to export</source>
        <translation>este eixo não tem controlador digital para exportar</translation>
    </message>
</context>
<context>
    <name>session_no_linuxcnc_pid</name>
    <message>
        <source>a %1 axis has no LinuxCNC pid equivalent</source>
        <translation>um eixo %1 não tem equivalente no pid do LinuxCNC</translation>
    </message>
</context>
<context>
    <name>session_no_loop_to_analyse</name>
    <message>
        <source>the axis has no loop to analyse</source>
        <translation>o eixo não tem malha para analisar</translation>
    </message>
</context>
<context>
    <name>session_no_mode_spectrum</name>
    <message>
        <source>there is no flexible mode to take a spectrum of</source>
        <translation>não há modo flexível do qual tirar um espectro</translation>
    </message>
</context>
<context>
    <name>session_no_model_feedforward</name>
    <message>
        <source>a %1 axis has no feedforward from a continuous model (pole placement&apos;s model-inverse feedforward is its ZPETC)</source>
        <translation>um eixo %1 não tem pré-alimentação de um modelo contínuo (a pré-alimentação por modelo inverso da alocação de polos é seu ZPETC)</translation>
    </message>
</context>
<context>
    <name>session_no_module</name>
    <message>
        <source>no module to register</source>
        <translation>nenhum módulo para registrar</translation>
    </message>
</context>
<context>
    <name>session_no_parameter</name>
    <message>
        <source>has no parameter %1</source>
        <translation>não tem o parâmetro %1</translation>
    </message>
</context>
<context>
    <name>session_not_a_finite_gain</name>
    <message>
        <source>%1 is not a finite gain &gt;= 0</source>
        <translation>%1 não é um ganho finito &gt;= 0</translation>
    </message>
</context>
<context>
    <name>session_not_zero_or_one</name>
    <message>
        <source>must be 0 or 1, not %1</source>
        <translation>deve ser 0 ou 1, não %1</translation>
    </message>
</context>
<context>
    <name>session_out_of_reach</name>
    <message>
        <source>the trajectory is out of the plant&apos;s reach: holding %1 mm needs %2 V (the model&apos;s steady gain B(1)/A(1) = %3 mm/V), beyond the %4 V limit</source>
        <translation>a trajetória está fora do alcance da planta: manter %1 mm precisa de %2 V (o ganho estático do modelo B(1)/A(1) = %3 mm/V), além do limite de %4 V</translation>
    </message>
</context>
<context>
    <name>session_parameter_out_of_range</name>
    <message>
        <source>%1 is out of range: %2 must be within %3 .. %4</source>
        <translation>%1 está fora do intervalo: %2 deve estar entre %3 .. %4</translation>
    </message>
</context>
<context>
    <name>session_parameter_out_of_range_unit</name>
    <message>
        <source>%1 is out of range: %2 must be within %3 .. %4 %5</source>
        <translation>%1 está fora do intervalo: %2 deve estar entre %3 .. %4 %5</translation>
    </message>
</context>
<context>
    <name>session_period_longer_than_run</name>
    <message>
        <source>%1 s is longer than the program&apos;s run (%2 s)</source>
        <translation>%1 s é mais longo que a execução do programa (%2 s)</translation>
    </message>
</context>
<context>
    <name>session_pid_equation_controller</name>
    <message>
        <source>C(s) = (P + I/s + D s/(Tf s + 1)) / u,  Tf = %1 s, u = %2 model units per mm</source>
        <translation>C(s) = (P + I/s + D s/(Tf s + 1)) / u,  Tf = %1 s, u = %2 unidades do modelo por mm</translation>
    </message>
</context>
<context>
    <name>session_pid_equation_feedforward</name>
    <message>
        <source>FF1 = %1, FF2 = %2, FF3 = %3 (model inverse: a2 u/k0 = %4, a1 u/k0 = %5, u/k0 = %6)</source>
        <translation>FF1 = %1, FF2 = %2, FF3 = %3 (inversa do modelo: a2 u/k0 = %4, a1 u/k0 = %5, u/k0 = %6)</translation>
    </message>
</context>
<context>
    <name>session_pid_no_feedback</name>
    <message>
        <source>P, I and D are all 0: the axis has no feedback</source>
        <translation>P, I e D são todos 0: o eixo não tem realimentação</translation>
    </message>
</context>
<context>
    <name>session_pid_no_notch</name>
    <message>
        <source>a PID + feedforward axis runs LinuxCNC&apos;s pid, which has no notch stage: set the centre to 0, or design the axis by Guillemin-Truxal, whose PI takes the notch</source>
        <translation>um eixo PID + pré-alimentação executa o pid do LinuxCNC, que não tem estágio notch: ajuste o centro para 0, ou projete o eixo por Guillemin-Truxal, cujo PI aceita o notch</translation>
    </message>
</context>
<context>
    <name>session_pid_zero_negative_gain</name>
    <message>
        <source>that zero needs a negative P, I or D</source>
        <translation>esse zero precisa de um P, I ou D negativo</translation>
    </message>
</context>
<context>
    <name>session_pid_zero_not_in_lhp</name>
    <message>
        <source>a zero in the right half plane (or on the axis) would not be a PID&apos;s</source>
        <translation>um zero no semiplano direito (ou no eixo) não seria de um PID</translation>
    </message>
</context>
<context>
    <name>session_program_line</name>
    <message>
        <source>program line %1</source>
        <translation>linha %1 do programa</translation>
    </message>
</context>
<context>
    <name>session_program_no_closed_form</name>
    <message>
        <source>a G-code program&apos;s feed profile has no closed form for the script; export the simulated signals as CSV instead</source>
        <translation>o perfil de avanço de um programa G-code não tem forma fechada para o script; exporte os sinais simulados como CSV</translation>
    </message>
</context>
<context>
    <name>session_shaper_longer_than_move</name>
    <message>
        <source>the %1 shaper at %2 Hz lasts %3 s, longer than the move of %4 s: raise the frequency or shorten the shaper</source>
        <translation>o modelador %1 em %2 Hz dura %3 s, mais que o movimento de %4 s: aumente a frequência ou encurte o modelador</translation>
    </message>
</context>
<context>
    <name>session_simulated_not_finite</name>
    <message>
        <source>the simulated %1 is %2 at t = %3 s (an unstable loop, or model_unit_scale or the trajectory out of range); nothing was exported</source>
        <translation>o %1 simulado é %2 em t = %3 s (uma malha instável, ou model_unit_scale ou a trajetória fora do intervalo); nada foi exportado</translation>
    </message>
</context>
<context>
    <name>session_single_sample</name>
    <message>
        <source>gives a single sample (step %1 s, duration %2 s); at least two samples are needed for the metrics</source>
        <translation>dá uma única amostra (passo %1 s, duração %2 s); são necessárias pelo menos duas amostras para as métricas</translation>
    </message>
</context>
<context>
    <name>session_spectrum_axis</name>
    <message>
        <source>must be x, y, z or sum</source>
        <translation>deve ser x, y, z ou sum</translation>
    </message>
</context>
<context>
    <name>session_t1_outside_unit_circle</name>
    <message>
        <source>the desired pole -t1 must lie inside the unit circle (|t1| &lt; 1)</source>
        <translation>o polo desejado -t1 deve ficar dentro do círculo unitário (|t1| &lt; 1)</translation>
    </message>
</context>
<context>
    <name>session_the_move</name>
    <message>
        <source>the move</source>
        <translation>o movimento</translation>
    </message>
</context>
<context>
    <name>session_too_many_pairs</name>
    <message>
        <source>%1 values of kp and %2 of ki make %3 pairs: at most %4</source>
        <translation>%1 valores de kp e %2 de ki formam %3 pares: no máximo %4</translation>
    </message>
</context>
<context>
    <name>session_too_many_samples</name>
    <message>
        <source>the run needs more samples than this machine holds</source>
        <translation>a execução precisa de mais amostras do que esta máquina comporta</translation>
    </message>
</context>
<context>
    <name>session_vibration_arx_axis</name>
    <message>
        <source>a pole-placement axis runs its ARX model, which holds whatever mode its data showed: the flexible mode and the notch apply to continuous plants</source>
        <translation>um eixo de alocação de polos executa seu modelo ARX, que contém qualquer modo que seus dados mostraram: o modo flexível e o notch se aplicam a plantas contínuas</translation>
    </message>
</context>
<context>
    <name>sim_axes_share_ts</name>
    <message>
        <source>the two axes must share one sample time</source>
        <translation>os dois eixos devem ter o mesmo período de amostragem</translation>
    </message>
</context>
<context>
    <name>sim_batch_lanes</name>
    <message>
        <source>the results and moves must have one entry per loop</source>
        <translation>os resultados e os movimentos devem ter uma entrada por malha</translation>
    </message>
</context>
<context>
    <name>sim_batch_width</name>
    <message>
        <source>must be 1, 2, 4 or 8</source>
        <translation>deve ser 1, 2, 4 ou 8</translation>
    </message>
</context>
<context>
    <name>sim_between_zero_one</name>
    <message>
        <source>must be between 0 and 1</source>
        <translation>deve estar entre 0 e 1</translation>
    </message>
</context>
<context>
    <name>sim_coupling_periods_differ</name>
    <message>
        <source>needs both axes at one controller period: the x axis runs every %1 s, the y axis every %2 s</source>
        <translation>precisa dos dois eixos com um mesmo período do controlador: o eixo x executa a cada %1 s, o eixo y a cada %2 s</translation>
    </message>
</context>
<context>
    <name>sim_coupling_samples_differ</name>
    <message>
        <source>the two axes&apos; runs do not have the same samples</source>
        <translation>as execuções dos dois eixos não têm as mesmas amostras</translation>
    </message>
</context>
<context>
    <name>sim_dac_bits</name>
    <message>
        <source>must be an integer in 0..32 (0: ideal DAC)</source>
        <translation>deve ser um inteiro em 0..32 (0: DAC ideal)</translation>
    </message>
</context>
<context>
    <name>sim_dac_needs_umax</name>
    <message>
        <source>a DAC needs a finite actuator limit umax (its full scale)</source>
        <translation>um DAC precisa de um limite finito do atuador umax (seu fundo de escala)</translation>
    </message>
</context>
<context>
    <name>sim_digital_implementation_finding</name>
    <message>
        <source>the digital implementation: %1</source>
        <translation>a implementação digital: %1</translation>
    </message>
</context>
<context>
    <name>sim_discretization_overflows</name>
    <message>
        <source>the plant&apos;s discretization at this sample time overflows</source>
        <translation>a discretização da planta com este período de amostragem estoura</translation>
    </message>
</context>
<context>
    <name>sim_encoder_resolution</name>
    <message>
        <source>must be a finite number &gt;= 0 (mm per count; 0: ideal)</source>
        <translation>deve ser um número finito &gt;= 0 (mm por contagem; 0: ideal)</translation>
    </message>
</context>
<context>
    <name>sim_envelope_invalid</name>
    <message>
        <source>needs a finite final value and a band in (0, 1)</source>
        <translation>precisa de um valor final finito e de uma faixa em (0, 1)</translation>
    </message>
</context>
<context>
    <name>sim_filter_not_causal</name>
    <message>
        <source>the z^0 coefficient must be nonzero (causal filter)</source>
        <translation>o coeficiente de z^0 deve ser não nulo (filtro causal)</translation>
    </message>
</context>
<context>
    <name>sim_finite_nonzero</name>
    <message>
        <source>must be a finite number other than zero</source>
        <translation>deve ser um número finito diferente de zero</translation>
    </message>
</context>
<context>
    <name>sim_fractions_order</name>
    <message>
        <source>must satisfy 0 &lt;= low &lt; high &lt;= 1</source>
        <translation>deve satisfazer 0 &lt;= low &lt; high &lt;= 1</translation>
    </message>
</context>
<context>
    <name>sim_hunting_at_rest</name>
    <message>
        <source>hunting at rest: the integral action broke the table free %1 after the move (%2 um peak to peak): integral action against stiction</source>
        <translation>oscilação em repouso (hunting): a ação integral destravou a mesa %1 após o movimento (%2 um pico a pico): ação integral contra o atrito estático</translation>
    </message>
</context>
<context>
    <name>sim_integer_up_to</name>
    <message>
        <source>must be an integer in 0..%1</source>
        <translation>deve ser um inteiro em 0..%1</translation>
    </message>
</context>
<context>
    <name>sim_lie_in_zero_one</name>
    <message>
        <source>must lie in (0, 1)</source>
        <translation>deve estar em (0, 1)</translation>
    </message>
</context>
<context>
    <name>sim_more_than</name>
    <message>
        <source>more than %1</source>
        <translation>mais de %1</translation>
    </message>
</context>
<context>
    <name>sim_move_not_finite</name>
    <message>
        <source>start, target and end time must be finite numbers</source>
        <translation>início, alvo e instante final devem ser números finitos</translation>
    </message>
</context>
<context>
    <name>sim_must_be_finite</name>
    <message>
        <source>must be finite</source>
        <translation>deve ser finito</translation>
    </message>
</context>
<context>
    <name>sim_needs_one_sample</name>
    <message>
        <source>needs at least one sample</source>
        <translation>precisa de pelo menos uma amostra</translation>
    </message>
</context>
<context>
    <name>sim_needs_samples</name>
    <message>
        <source>needs %1 samples, got %2</source>
        <translation>precisa de %1 amostras, recebeu %2</translation>
    </message>
</context>
<context>
    <name>sim_needs_samples_preview</name>
    <message>
        <source>needs %1 samples (run length plus preview), got %2</source>
        <translation>precisa de %1 amostras (duração da execução mais a antecipação), recebeu %2</translation>
    </message>
</context>
<context>
    <name>sim_no_sample_after_ramp_in</name>
    <message>
        <source>no sample after the ramp-in</source>
        <translation>nenhuma amostra após a rampa de entrada</translation>
    </message>
</context>
<context>
    <name>sim_once</name>
    <message>
        <source>once</source>
        <translation>uma vez</translation>
    </message>
</context>
<context>
    <name>sim_one_sample_per_reference</name>
    <message>
        <source>must have one sample per reference sample</source>
        <translation>deve ter uma amostra por amostra da referência</translation>
    </message>
</context>
<context>
    <name>sim_plant_cannot_rest_away</name>
    <message>
        <source>the plant has no pole at s = 0, so it cannot rest away from 0</source>
        <translation>a planta não tem polo em s = 0, portanto não pode repousar fora de 0</translation>
    </message>
</context>
<context>
    <name>sim_position_beyond_limit</name>
    <message>
        <source>%1 is beyond the 1e9 mm (1000 km) that any table could move; refused before it overflows the simulation</source>
        <translation>%1 está além dos 1e9 mm (1000 km) que qualquer mesa poderia percorrer; recusado antes que estoure a simulação</translation>
    </message>
</context>
<context>
    <name>sim_realization_loses_stability</name>
    <message>
        <source>the loop&apos;s state-space realization loses the closed loop&apos;s stability to round-off (an eigenvalue at %1 1/s for a stable loop): the plant&apos;s coefficients are too far apart in scale to simulate</source>
        <translation>a realização em espaço de estados da malha perde a estabilidade da malha fechada por arredondamento (um autovalor em %1 1/s para uma malha estável): os coeficientes da planta têm escalas distantes demais para simular</translation>
    </message>
</context>
<context>
    <name>sim_run_has_no_samples</name>
    <message>
        <source>the run has no samples</source>
        <translation>a execução não tem amostras</translation>
    </message>
</context>
<context>
    <name>sim_sample_not_finite</name>
    <message>
        <source>sample %1 is not a finite number</source>
        <translation>a amostra %1 não é um número finito</translation>
    </message>
</context>
<context>
    <name>sim_samples_beyond_limit</name>
    <message>
        <source>needs %1 samples at this dt; the limit is %2</source>
        <translation>precisa de %1 amostras com este dt; o limite é %2</translation>
    </message>
</context>
<context>
    <name>sim_samples_beyond_memory</name>
    <message>
        <source>needs %1 samples at this dt; the limit is %2 on this machine (%3 % of its %4 GB of memory at %5 bytes per sample)</source>
        <translation>precisa de %1 amostras com este dt; o limite é %2 nesta máquina (%3 % dos seus %4 GB de memória a %5 bytes por amostra)</translation>
    </message>
</context>
<context>
    <name>sim_samples_range</name>
    <message>
        <source>must lie in 10 .. 1000000</source>
        <translation>deve estar em 10 .. 1000000</translation>
    </message>
</context>
<context>
    <name>sim_shaped_sizes_differ</name>
    <message>
        <source>differs in size from shaped.x</source>
        <translation>difere em tamanho de shaped.x</translation>
    </message>
</context>
<context>
    <name>sim_shaper_longer_than_move</name>
    <message>
        <source>the shaper lasts %1 s, longer than the move of %2 s</source>
        <translation>o modelador de entrada dura %1 s, mais que o movimento de %2 s</translation>
    </message>
</context>
<context>
    <name>sim_shaper_not_number</name>
    <message>
        <source>has a value that is not a number</source>
        <translation>tem um valor que não é um número</translation>
    </message>
</context>
<context>
    <name>sim_shaper_sizes</name>
    <message>
        <source>needs as many impulse times as amplitudes (at least one)</source>
        <translation>precisa de tantos instantes de impulso quanto amplitudes (pelo menos um)</translation>
    </message>
</context>
<context>
    <name>sim_shaper_times_order</name>
    <message>
        <source>impulse times must start at 0 and increase</source>
        <translation>os instantes dos impulsos devem começar em 0 e crescer</translation>
    </message>
</context>
<context>
    <name>sim_signals_different_lengths</name>
    <message>
        <source>signals of different lengths</source>
        <translation>sinais de comprimentos diferentes</translation>
    </message>
</context>
<context>
    <name>sim_single_sample</name>
    <message>
        <source>gives a single sample (Ts %1 s, duration %2 s); at least two samples are needed for the metrics</source>
        <translation>dá uma única amostra (Ts %1 s, duração %2 s); as métricas precisam de pelo menos duas amostras</translation>
    </message>
</context>
<context>
    <name>sim_stick_slip_during_move</name>
    <message>
        <source>stick-slip during the move: the table stopped %1 while the reference kept moving (first at t = %2 s)</source>
        <translation>stick-slip durante o movimento: a mesa parou %1 enquanto a referência continuava a se mover (a primeira em t = %2 s)</translation>
    </message>
</context>
<context>
    <name>sim_substeps_not_negative</name>
    <message>
        <source>must be &gt;= 0 (0: automatic)</source>
        <translation>deve ser &gt;= 0 (0: automático)</translation>
    </message>
</context>
<context>
    <name>sim_table_controller_states</name>
    <message>
        <source>has more states than the friction simulation holds (%1)</source>
        <translation>tem mais estados do que a simulação com atrito comporta (%1)</translation>
    </message>
</context>
<context>
    <name>sim_table_electrical_pole</name>
    <message>
        <source>the electrical pole must be &gt; 0 (a2 = 0 leaves one pole at 0, which can only be the mechanical one)</source>
        <translation>o polo elétrico deve ser &gt; 0 (a2 = 0 deixa um polo em 0, que só pode ser o mecânico)</translation>
    </message>
</context>
<context>
    <name>sim_table_plant_shape</name>
    <message>
        <source>must be k0 / (s (s^2 + a1 s + a2)) with k0 &gt; 0 for the table&apos;s friction</source>
        <translation>deve ser k0 / (s (s^2 + a1 s + a2)) com k0 &gt; 0 para o atrito da mesa</translation>
    </message>
</context>
<context>
    <name>sim_table_poles_not_real</name>
    <message>
        <source>the poles of s^2 + a1 s + a2 must be real and stable to split the plant into an electrical lag and a moving mass</source>
        <translation>os polos de s^2 + a1 s + a2 devem ser reais e estáveis para separar a planta em um atraso elétrico e uma massa móvel</translation>
    </message>
</context>
<context>
    <name>sim_tf_after_t0</name>
    <message>
        <source>must be later than t0</source>
        <translation>deve ser posterior a t0</translation>
    </message>
</context>
<context>
    <name>sim_time_overflows</name>
    <message>
        <source>the last sample time of the run, or omega times it, overflows a double</source>
        <translation>o último instante de amostragem da execução, ou ômega vezes ele, excede a faixa de um double</translation>
    </message>
</context>
<context>
    <name>sim_times</name>
    <message>
        <source>%1 times</source>
        <translation>%1 vezes</translation>
    </message>
</context>
<context>
    <name>sim_txy_different_lengths</name>
    <message>
        <source>t, x and y have different lengths</source>
        <translation>t, x e y têm comprimentos diferentes</translation>
    </message>
</context>
<context>
    <name>sim_ty_same_length</name>
    <message>
        <source>t and y must have the same length</source>
        <translation>t e y devem ter o mesmo comprimento</translation>
    </message>
</context>
<context>
    <name>sim_ty_same_length_two</name>
    <message>
        <source>t and y must have the same length, at least 2</source>
        <translation>t e y devem ter o mesmo comprimento, pelo menos 2</translation>
    </message>
</context>
<context>
    <name>sim_umax_positive</name>
    <message>
        <source>must be greater than zero (infinity for no limit)</source>
        <translation>deve ser maior que zero (infinito para nenhum limite)</translation>
    </message>
</context>
<context>
    <name>sim_y_x_sizes</name>
    <message>
        <source>has %1 samples, x has %2</source>
        <translation>tem %1 amostras, x tem %2</translation>
    </message>
</context>
<context>
    <name>sim_zpetc_den_zero</name>
    <message>
        <source>the feedforward&apos;s z^0 denominator coefficient is zero</source>
        <translation>o coeficiente de z^0 do denominador da pré-alimentação é zero</translation>
    </message>
</context>
<context>
    <name>study_best_at_lower_edge</name>
    <message>
        <source>%1 = %2 (the best design) is the lower end of the %3 range %4..%5: the optimum may lie below; widen the %6 range below %7</source>
        <translation>%1 = %2 (o melhor projeto) é o extremo inferior da faixa de %3 %4..%5: o ótimo pode estar abaixo; amplie a faixa de %6 abaixo de %7</translation>
    </message>
</context>
<context>
    <name>study_best_at_upper_edge</name>
    <message>
        <source>%1 = %2 (the best design) is the upper end of the %3 range %4..%5: the optimum may lie above; widen the %6 range beyond %7</source>
        <translation>%1 = %2 (o melhor projeto) é o extremo superior da faixa de %3 %4..%5: o ótimo pode estar acima; amplie a faixa de %6 além de %7</translation>
    </message>
</context>
<context>
    <name>study_bounds_not_finite</name>
    <message>
        <source>the bounds must be finite numbers</source>
        <translation>os limites devem ser números finitos</translation>
    </message>
</context>
<context>
    <name>study_cancelled_statistics</name>
    <message>
        <source>cancelled: the statistics cover the plants computed before</source>
        <translation>cancelado: as estatísticas cobrem as plantas calculadas antes</translation>
    </message>
</context>
<context>
    <name>study_change_at_least</name>
    <message>
        <source>%1 &gt;= %2</source>
        <translation>%1 &gt;= %2</translation>
    </message>
</context>
<context>
    <name>study_change_at_most</name>
    <message>
        <source>%1 &lt;= %2</source>
        <translation>%1 &lt;= %2</translation>
    </message>
</context>
<context>
    <name>study_circle_or_path</name>
    <message>
        <source>give either a circle or a path</source>
        <translation>dê um círculo ou um caminho</translation>
    </message>
</context>
<context>
    <name>study_continuous_run_samples</name>
    <message>
        <source>a continuous run has exactly the reference&apos;s samples</source>
        <translation>uma execução contínua tem exatamente as amostras da referência</translation>
    </message>
</context>
<context>
    <name>study_controller_or_loop</name>
    <message>
        <source>give either a continuous controller or a discrete loop</source>
        <translation>dê um controlador contínuo ou uma malha discreta</translation>
    </message>
</context>
<context>
    <name>study_count_range</name>
    <message>
        <source>the count must be from 1 to %1</source>
        <translation>a contagem deve estar entre 1 e %1</translation>
    </message>
</context>
<context>
    <name>study_coupling_one_grid</name>
    <message>
        <source>needs both axes on one grid with a direction for each sample</source>
        <translation>precisa dos dois eixos em uma só grade com uma direção para cada amostra</translation>
    </message>
</context>
<context>
    <name>study_covariance_not_finite</name>
    <message>
        <source>holds a value that is not finite</source>
        <translation>contém um valor que não é finito</translation>
    </message>
</context>
<context>
    <name>study_covariance_not_psd</name>
    <message>
        <source>is not positive semi-definite</source>
        <translation>não é positiva semidefinida</translation>
    </message>
</context>
<context>
    <name>study_covariance_not_symmetric</name>
    <message>
        <source>is not symmetric</source>
        <translation>não é simétrica</translation>
    </message>
</context>
<context>
    <name>study_covariance_size</name>
    <message>
        <source>must be %1 x %2 (one row per parameter)</source>
        <translation>deve ser %1 x %2 (uma linha por parâmetro)</translation>
    </message>
</context>
<context>
    <name>study_criterion_clipped_time</name>
    <message>
        <source>clipped time</source>
        <translation>tempo saturado</translation>
    </message>
</context>
<context>
    <name>study_criterion_gain_margin</name>
    <message>
        <source>gain margin</source>
        <translation>margem de ganho</translation>
    </message>
</context>
<context>
    <name>study_criterion_overshoot</name>
    <message>
        <source>step overshoot</source>
        <translation>sobressinal ao degrau</translation>
    </message>
</context>
<context>
    <name>study_criterion_phase_margin</name>
    <message>
        <source>phase margin</source>
        <translation>margem de fase</translation>
    </message>
</context>
<context>
    <name>study_criterion_settle_time</name>
    <message>
        <source>settle time after the move</source>
        <translation>tempo de acomodação após o movimento</translation>
    </message>
</context>
<context>
    <name>study_criterion_settling_time</name>
    <message>
        <source>step settling time</source>
        <translation>tempo de acomodação ao degrau</translation>
    </message>
</context>
<context>
    <name>study_criterion_stability</name>
    <message>
        <source>stability</source>
        <translation>estabilidade</translation>
    </message>
</context>
<context>
    <name>study_criterion_tracking_error</name>
    <message>
        <source>max tracking error</source>
        <translation>erro de seguimento máx.</translation>
    </message>
</context>
<context>
    <name>study_design_at</name>
    <message>
        <source>wn = %1 rad/s, kp = %2</source>
        <translation>wn = %1 rad/s, kp = %2</translation>
    </message>
</context>
<context>
    <name>study_designs_same_length</name>
    <message>
        <source>wn, kp and the results must have the same length</source>
        <translation>wn, kp e os resultados devem ter o mesmo comprimento</translation>
    </message>
</context>
<context>
    <name>study_friction_real_poles</name>
    <message>
        <source>with the table&apos;s friction the poles of s^2 + a1 s + a2 must stay real (a1^2 &gt;= 4 a2) over the ranges of a1 and a2: narrow them</source>
        <translation>com o atrito da mesa os polos de s^2 + a1 s + a2 devem permanecer reais (a1^2 &gt;= 4 a2) nas faixas de a1 e a2: estreite-as</translation>
    </message>
</context>
<context>
    <name>study_from_to</name>
    <message>
        <source>must be from %1 to %2</source>
        <translation>deve estar entre %1 e %2</translation>
    </message>
</context>
<context>
    <name>study_least_violating</name>
    <message>
        <source>least-violating design: %1 (point %2)</source>
        <translation>projeto que menos viola: %1 (ponto %2)</translation>
    </message>
</context>
<context>
    <name>study_least_violating_no_relaxing</name>
    <message>
        <source>least-violating design: %1 (point %2); relaxing a limit does not make it pass (it clips the actuator, never settles, or has no positive margin)</source>
        <translation>projeto que menos viola: %1 (ponto %2); relaxar um limite não o faz passar (satura o atuador, nunca se acomoda ou não tem margem positiva)</translation>
    </message>
</context>
<context>
    <name>study_least_violating_relaxed</name>
    <message>
        <source>least-violating design: %1 (point %2); it meets the specification with %3</source>
        <translation>projeto que menos viola: %1 (ponto %2); atende à especificação com %3</translation>
    </message>
</context>
<context>
    <name>study_limit_fails_everywhere</name>
    <message>
        <source>the %1 limit (%2) fails at every design of the grid</source>
        <translation>o limite de %1 (%2) falha em todo projeto da grade</translation>
    </message>
</context>
<context>
    <name>study_limit_fails_largest</name>
    <message>
        <source>the %1 limit (%2) fails at every design of the grid; the largest %3 found is %4 at %5</source>
        <translation>o limite de %1 (%2) falha em todo projeto da grade; a maior %3 encontrada é %4 em %5</translation>
    </message>
</context>
<context>
    <name>study_limit_fails_smallest</name>
    <message>
        <source>the %1 limit (%2) fails at every design of the grid; the smallest %3 found is %4 at %5</source>
        <translation>o limite de %1 (%2) falha em todo projeto da grade; o menor %3 encontrado é %4 em %5</translation>
    </message>
</context>
<context>
    <name>study_minimum_above_maximum</name>
    <message>
        <source>the minimum is greater than the maximum</source>
        <translation>o mínimo é maior que o máximo</translation>
    </message>
</context>
<context>
    <name>study_minimum_not_positive</name>
    <message>
        <source>the minimum must be greater than zero</source>
        <translation>o mínimo deve ser maior que zero</translation>
    </message>
</context>
<context>
    <name>study_no_feasible_design</name>
    <message>
        <source>no design of the grid meets the specification</source>
        <translation>nenhum projeto da grade atende à especificação</translation>
    </message>
</context>
<context>
    <name>study_no_sample_on_segment</name>
    <message>
        <source>no sample on a measured segment</source>
        <translation>nenhuma amostra em um segmento medido</translation>
    </message>
</context>
<context>
    <name>study_no_scale</name>
    <message>
        <source>give at least one scale</source>
        <translation>dê pelo menos uma escala</translation>
    </message>
</context>
<context>
    <name>study_no_such_parameter</name>
    <message>
        <source>no parameter &apos;%1&apos; in this plant (it has %2)</source>
        <translation>não há parâmetro &apos;%1&apos; nesta planta (ela tem %2)</translation>
    </message>
</context>
<context>
    <name>study_nominal_not_finite</name>
    <message>
        <source>the nominal design&apos;s run is not finite (it diverges): there is no contour to compare with</source>
        <translation>a execução do projeto nominal não é finita (diverge): não há contorno para comparar</translation>
    </message>
</context>
<context>
    <name>study_none_settles</name>
    <message>
        <source>no design of the grid settles into the %1 mm window within the run (limit %2 s after the move)</source>
        <translation>nenhum projeto da grade se acomoda na janela de %1 mm dentro da execução (limite %2 s após o movimento)</translation>
    </message>
</context>
<context>
    <name>study_none_stable</name>
    <message>
        <source>no design of the grid is stable</source>
        <translation>nenhum projeto da grade é estável</translation>
    </message>
</context>
<context>
    <name>study_other_window</name>
    <message>
        <source>the study measured the settle with another window; run it again</source>
        <translation>o estudo mediu a acomodação com outra janela; execute-o novamente</translation>
    </message>
</context>
<context>
    <name>study_outside_search_box</name>
    <message>
        <source>is outside the search box</source>
        <translation>está fora da caixa de busca</translation>
    </message>
</context>
<context>
    <name>study_phase_margin_at_most_180</name>
    <message>
        <source>must be at most 180 degrees</source>
        <translation>deve ser no máximo 180 graus</translation>
    </message>
</context>
<context>
    <name>study_plant_needs_parameter</name>
    <message>
        <source>a continuous plant needs the parameter %1</source>
        <translation>uma planta contínua precisa do parâmetro %1</translation>
    </message>
</context>
<context>
    <name>study_range_percent</name>
    <message>
        <source>must be from 0 to below 100 %</source>
        <translation>deve estar entre 0 e menos de 100 %</translation>
    </message>
</context>
<context>
    <name>study_reference_too_short</name>
    <message>
        <source>the reference must hold the run (at least 2 samples) and the preview</source>
        <translation>a referência deve conter a execução (pelo menos 2 amostras) e a antecipação</translation>
    </message>
</context>
<context>
    <name>study_scale_reason</name>
    <message>
        <source>scale %1: %2</source>
        <translation>escala %1: %2</translation>
    </message>
</context>
<context>
    <name>study_search_needs_feasible</name>
    <message>
        <source>the search starts from a feasible design</source>
        <translation>a busca parte de um projeto viável</translation>
    </message>
</context>
<context>
    <name>study_steps_not_finite</name>
    <message>
        <source>the steps must be finite and &gt;= 0</source>
        <translation>os passos devem ser finitos e &gt;= 0</translation>
    </message>
</context>
<context>
    <name>study_sweep_cancelled</name>
    <message>
        <source>cancelled: %1 of %2 grid points computed, no refinement</source>
        <translation>cancelado: %1 de %2 pontos da grade calculados, sem refinamento</translation>
    </message>
</context>
<context>
    <name>study_threads_range</name>
    <message>
        <source>must be from 0 (all cores) to 1024</source>
        <translation>deve estar entre 0 (todos os núcleos) e 1024</translation>
    </message>
</context>
<context>
    <name>study_time_base_empty</name>
    <message>
        <source>the time base is empty</source>
        <translation>a base de tempo está vazia</translation>
    </message>
</context>
<context>
    <name>study_time_base_not_increasing</name>
    <message>
        <source>the time base must be finite and increasing (sample %1)</source>
        <translation>a base de tempo deve ser finita e crescente (amostra %1)</translation>
    </message>
</context>
<context>
    <name>study_too_many_corners</name>
    <message>
        <source>%1 uncertain parameters have too many corners (at most 16 parameters)</source>
        <translation>%1 parâmetros incertos têm vértices demais (no máximo 16 parâmetros)</translation>
    </message>
</context>
<context>
    <name>study_unstable_plant_pairs</name>
    <message>
        <source>%1 plant pairs are unstable or diverged with these controllers; they are listed, not in the statistics</source>
        <translation>%1 pares de plantas são instáveis ou divergiram com estes controladores; estão listados, não nas estatísticas</translation>
    </message>
</context>
<context>
    <name>study_unstable_plants</name>
    <message>
        <source>%1 plants are unstable or diverged with this controller; they are listed, not in the statistics</source>
        <translation>%1 plantas são instáveis ou divergiram com este controlador; estão listadas, não nas estatísticas</translation>
    </message>
</context>
<context>
    <name>study_value_decibels</name>
    <message>
        <source>%1 dB</source>
        <translation>%1 dB</translation>
    </message>
</context>
<context>
    <name>study_value_degrees</name>
    <message>
        <source>%1 deg</source>
        <translation>%1 deg</translation>
    </message>
</context>
<context>
    <name>study_value_percent</name>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
</context>
<context>
    <name>study_value_percent_of_travel</name>
    <message>
        <source>%1 % of the travel</source>
        <translation>%1 % do curso</translation>
    </message>
</context>
<context>
    <name>study_value_seconds</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
</context>
<context>
    <name>study_zero_or_more</name>
    <message>
        <source>must be zero or more</source>
        <translation>deve ser zero ou mais</translation>
    </message>
</context>
<context>
    <name>study_zpetc_sensitivity_needs_zpetc</name>
    <message>
        <source>the ZPETC sensitivity needs a pole-placement axis with ZPETC enabled</source>
        <translation>a sensibilidade do ZPETC precisa de um eixo de alocação de polos com o ZPETC ativado</translation>
    </message>
</context>
<context>
    <name>study_zpetc_without_design</name>
    <message>
        <source>ZPETC is enabled without its design</source>
        <translation>o ZPETC está ativado sem seu projeto</translation>
    </message>
</context>
<context>
    <name>xyt::AntiWindup</name>
    <message>
        <source>none</source>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>clamp</source>
        <translation>grampeamento</translation>
    </message>
    <message>
        <source>back-calculation</source>
        <translation>retrocálculo</translation>
    </message>
</context>
<context>
    <name>xyt::CoreText</name>
    <message>
        <source>feedforward</source>
        <translation>pré-alimentação</translation>
    </message>
</context>
<context>
    <name>xyt::Discretization</name>
    <message>
        <source>tustin</source>
        <translation>Tustin</translation>
    </message>
    <message>
        <source>backward-euler</source>
        <translation>Euler regressivo</translation>
    </message>
</context>
<context>
    <name>xyt::EstimationStatus</name>
    <message>
        <source>converged</source>
        <translation>convergiu</translation>
    </message>
    <message>
        <source>iteration-limit</source>
        <translation>limite de iterações</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <source>not-persistently-exciting</source>
        <translation>não persistentemente excitante</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>falhou</translation>
    </message>
</context>
<context>
    <name>xyt::MethodName</name>
    <message>
        <source>Guillemin-Truxal PI</source>
        <translation>PI de Guillemin-Truxal</translation>
    </message>
    <message>
        <source>PID + feedforward</source>
        <translation>PID + pré-alimentação</translation>
    </message>
    <message>
        <source>pole placement + ZPETC</source>
        <translation>alocação de polos + ZPETC</translation>
    </message>
</context>
<context>
    <name>xyt::ParameterLabel</name>
    <message>
        <source>Proportional gain P</source>
        <translation>Ganho proporcional P</translation>
    </message>
    <message>
        <source>Integral gain I</source>
        <translation>Ganho integral I</translation>
    </message>
    <message>
        <source>Derivative gain D</source>
        <translation>Ganho derivativo D</translation>
    </message>
    <message>
        <source>Position feedforward FF0</source>
        <translation>Pré-alimentação de posição FF0</translation>
    </message>
    <message>
        <source>Velocity feedforward FF1</source>
        <translation>Pré-alimentação de velocidade FF1</translation>
    </message>
    <message>
        <source>Acceleration feedforward FF2</source>
        <translation>Pré-alimentação de aceleração FF2</translation>
    </message>
    <message>
        <source>Jerk feedforward FF3</source>
        <translation>Pré-alimentação de jerk FF3</translation>
    </message>
    <message>
        <source>Bias</source>
        <translation>Polarização</translation>
    </message>
    <message>
        <source>Deadband</source>
        <translation>Zona morta</translation>
    </message>
    <message>
        <source>Integrator limit (0: none)</source>
        <translation>Limite do integrador (0: nenhum)</translation>
    </message>
    <message>
        <source>Output limit (0: umax)</source>
        <translation>Limite de saída (0: umax)</translation>
    </message>
    <message>
        <source>D filter Tf (0: none)</source>
        <translation>Filtro de D Tf (0: nenhum)</translation>
    </message>
    <message>
        <source>D on the measurement (1) or the error (0)</source>
        <translation>D sobre a medição (1) ou o erro (0)</translation>
    </message>
    <message>
        <source>Command derivatives: backward differences (0), trajectory (1)</source>
        <translation>Derivadas do comando: diferenças regressivas (0), trajetória (1)</translation>
    </message>
</context>
<context>
    <name>xyt::PresetName</name>
    <message>
        <source>lower-base</source>
        <translation>base inferior</translation>
    </message>
    <message>
        <source>upper-base</source>
        <translation>base superior</translation>
    </message>
    <message>
        <source>x-axis</source>
        <translation>eixo x</translation>
    </message>
    <message>
        <source>y-axis</source>
        <translation>eixo y</translation>
    </message>
</context>
<context>
    <name>xyt::files::SessionFile</name>
    <message>
        <source>must be %1 or %2</source>
        <translation>deve ser %1 ou %2</translation>
    </message>
    <message>
        <source>must be an object</source>
        <translation>deve ser um objeto</translation>
    </message>
    <message>
        <source>is missing</source>
        <translation>está faltando</translation>
    </message>
    <message>
        <source>must be a finite number</source>
        <translation>deve ser um número finito</translation>
    </message>
    <message>
        <source>must be greater than zero</source>
        <translation>deve ser maior que zero</translation>
    </message>
    <message>
        <source>must be a string</source>
        <translation>deve ser um texto</translation>
    </message>
    <message>
        <source>must be true or false</source>
        <translation>deve ser true ou false</translation>
    </message>
    <message>
        <source>must be an array of numbers</source>
        <translation>deve ser um vetor de números</translation>
    </message>
    <message>
        <source>must not be empty</source>
        <translation>não pode estar vazio</translation>
    </message>
    <message>
        <source>has %1 entries; at most %2 are allowed</source>
        <translation>tem %1 entradas; no máximo %2 são permitidas</translation>
    </message>
    <message>
        <source>must be an integer in %1..%2%3</source>
        <translation>deve ser um inteiro em %1..%2%3</translation>
    </message>
    <message>
        <source>%1: unknown field ignored</source>
        <translation>%1: campo desconhecido ignorado</translation>
    </message>
    <message>
        <source>must be a whole number of samples</source>
        <translation>deve ser um número inteiro de amostras</translation>
    </message>
    <message>
        <source>must be a finite number or null</source>
        <translation>deve ser um número finito ou null</translation>
    </message>
    <message>
        <source>must be an array of at most 1000 names</source>
        <translation>deve ser um vetor de no máximo 1000 nomes</translation>
    </message>
    <message>
        <source>must be an array as long as &quot;parameters&quot;</source>
        <translation>deve ser um vetor do mesmo tamanho que &quot;parameters&quot;</translation>
    </message>
    <message>
        <source>must be an array of %1 numbers (the %2 x %2 matrix, row by row)</source>
        <translation>deve ser um vetor de %1 números (a matriz %2 x %2, linha a linha)</translation>
    </message>
    <message>
        <source>must be &quot;faster&quot; or &quot;slower&quot;</source>
        <translation>deve ser &quot;faster&quot; ou &quot;slower&quot;</translation>
    </message>
    <message>
        <source>must be zv, mzv, zvd, zvdd, ei, 2hump_ei or 3hump_ei</source>
        <translation>deve ser zv, mzv, zvd, zvdd, ei, 2hump_ei ou 3hump_ei</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (mm per count; 0: ideal encoder)</source>
        <translation>deve ser &gt;= 0 (mm por contagem; 0: encoder ideal)</translation>
    </message>
    <message>
        <source> (0: ideal DAC)</source>
        <translation> (0: DAC ideal)</translation>
    </message>
    <message>
        <source>must be &quot;none&quot;, &quot;clamp&quot; or &quot;back-calculation&quot;</source>
        <translation>deve ser &quot;none&quot;, &quot;clamp&quot; ou &quot;back-calculation&quot;</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (s; 0: Tt = Ti = kp/ki)</source>
        <translation>deve ser &gt;= 0 (s; 0: Tt = Ti = kp/ki)</translation>
    </message>
    <message>
        <source>must be &quot;linear&quot; or &quot;circular&quot;</source>
        <translation>deve ser &quot;linear&quot; ou &quot;circular&quot;</translation>
    </message>
    <message>
        <source>must be named by 1 to 32 lower-case letters, digits or &apos;_&apos;</source>
        <translation>deve ter um nome de 1 a 32 letras minúsculas, dígitos ou &apos;_&apos;</translation>
    </message>
    <message>
        <source>must be within %1 .. %2 %3</source>
        <translation>deve estar entre %1 .. %2 %3</translation>
    </message>
    <message>
        <source>must be 1 to 16 lower-case letters or digits</source>
        <translation>deve ter de 1 a 16 letras minúsculas ou dígitos</translation>
    </message>
    <message>
        <source>must be nonzero</source>
        <translation>deve ser diferente de zero</translation>
    </message>
    <message>
        <source>must be nonzero (A is monic)</source>
        <translation>deve ser diferente de zero (A é mônico)</translation>
    </message>
    <message>
        <source>must be &quot;cubic&quot;, &quot;circle&quot; or &quot;gcode&quot;</source>
        <translation>deve ser &quot;cubic&quot;, &quot;circle&quot; ou &quot;gcode&quot;</translation>
    </message>
    <message>
        <source>must be later than t0</source>
        <translation>deve ser posterior a t0</translation>
    </message>
    <message>
        <source>must be &quot;cubic&quot; or &quot;quintic&quot;</source>
        <translation>deve ser &quot;cubic&quot; ou &quot;quintic&quot;</translation>
    </message>
    <message>
        <source>must be &gt;= 0</source>
        <translation>deve ser &gt;= 0</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (0 = none)</source>
        <translation>deve ser &gt;= 0 (0 = nenhum)</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (0 = automatic)</source>
        <translation>deve ser &gt;= 0 (0 = automático)</translation>
    </message>
    <message>
        <source>needs %1 samples at this dt; the limit is %2 on this machine</source>
        <translation>precisa de %1 amostras com este dt; o limite é %2 nesta máquina</translation>
    </message>
    <message>
        <source>must be an array of exactly two axes</source>
        <translation>deve ser um vetor de exatamente dois eixos</translation>
    </message>
    <message>
        <source>must differ from axes[0].id</source>
        <translation>deve ser diferente de axes[0].id</translation>
    </message>
    <message>
        <source>must be &quot;%1&quot;</source>
        <translation>deve ser &quot;%1&quot;</translation>
    </message>
    <message>
        <source>must be a whole number &gt;= 1</source>
        <translation>deve ser um número inteiro &gt;= 1</translation>
    </message>
    <message>
        <source>the file has format version %1; this XY Tune reads version %2 and older: please update XY Tune</source>
        <translation>o arquivo tem a versão de formato %1; este XY Tune lê a versão %2 e anteriores: atualize o XY Tune</translation>
    </message>
    <message>
        <source>must be &quot;tustin&quot; or &quot;backward-euler&quot;</source>
        <translation>deve ser &quot;tustin&quot; ou &quot;backward-euler&quot;</translation>
    </message>
    <message>
        <source>must be 0 .. 180 degrees</source>
        <translation>deve estar entre 0 .. 180 graus</translation>
    </message>
    <message>
        <source>must be &gt;= 0 dB</source>
        <translation>deve ser &gt;= 0 dB</translation>
    </message>
    <message>
        <source>must be an array</source>
        <translation>deve ser um vetor</translation>
    </message>
    <message>
        <source>not valid JSON: %1 at byte %2</source>
        <translation>JSON inválido: %1 no byte %2</translation>
    </message>
    <message>
        <source>appears more than once in its object; a key may be given only once</source>
        <translation>aparece mais de uma vez em seu objeto; uma chave só pode ser dada uma vez</translation>
    </message>
    <message>
        <source>not a session: the document must be a JSON object</source>
        <translation>não é uma sessão: o documento deve ser um objeto JSON</translation>
    </message>
</context>
<context>
    <name>xyt::ui::BodePlot</name>
    <message>
        <source>Bode diagram</source>
        <translation>Diagrama de Bode</translation>
    </message>
    <message>
        <source>magnitude (dB)</source>
        <translation>módulo (dB)</translation>
    </message>
    <message>
        <source>phase (°)</source>
        <translation>fase (°)</translation>
    </message>
    <message>
        <source>frequency ω (rad/s)</source>
        <translation>frequência ω (rad/s)</translation>
    </message>
    <message>
        <source>measured L = C H</source>
        <translation>L = C H medido</translation>
    </message>
    <message>
        <source>measured L = C H (%1)</source>
        <translation>L = C H medido (%1)</translation>
    </message>
    <message>
        <source>hover the plot: ω, |L| and ∠L of the open loop</source>
        <translation>passe o mouse sobre o gráfico: ω, |L| e ∠L da malha aberta</translation>
    </message>
    <message>
        <source>open loop L</source>
        <translation>malha aberta L</translation>
    </message>
    <message>
        <source>|S| sensitivity</source>
        <translation>|S| sensibilidade</translation>
    </message>
    <message>
        <source>|T| closed loop</source>
        <translation>|T| malha fechada</translation>
    </message>
    <message>
        <source>tracking, loop alone</source>
        <translation>seguimento, só a malha</translation>
    </message>
    <message>
        <source>tracking with %1</source>
        <translation>seguimento com %1</translation>
    </message>
    <message>
        <source>tracking with </source>
        <translation>seguimento com </translation>
    </message>
    <message>
        <source>L without the notch</source>
        <translation>L sem o notch</translation>
    </message>
    <message>
        <source> (PM %1°)</source>
        <translation> (MF %1°)</translation>
    </message>
    <message>
        <source>GM %1 dB at %2 rad/s</source>
        <translation>MG %1 dB em %2 rad/s</translation>
    </message>
    <message>
        <source> dB</source>
        <translation> dB</translation>
    </message>
    <message>
        <source>PM %1° at %2 rad/s</source>
        <translation>MF %1° em %2 rad/s</translation>
    </message>
    <message>
        <source>reference ω = %1</source>
        <translation>referência ω = %1</translation>
    </message>
    <message>
        <source>Nyquist π/Ts</source>
        <translation>Nyquist π/Ts</translation>
    </message>
    <message>
        <source>the closed loop is unstable: the margins are not robustness measures</source>
        <translation>a malha fechada é instável: as margens não são medidas de robustez</translation>
    </message>
    <message>
        <source>ω = %1 rad/s   |L| = %2 dB   ∠L = %3°</source>
        <translation>ω = %1 rad/s   |L| = %2 dB   ∠L = %3°</translation>
    </message>
    <message>
        <source>Bode diagram of the loop L(jω) = C(jω) G(jω): magnitude (dB) and phase (°) against ω (rad/s) on an adaptive grid, with the gain and phase margins drawn where they are read (green when they meet the specification&apos;s minima, red when not), and |S| = |1/(1 + L)| and |T| = |L/(1 + L)|.</source>
        <translation>Diagrama de Bode da malha L(jω) = C(jω) G(jω): módulo (dB) e fase (°) em função de ω (rad/s) numa grade adaptativa, com as margens de ganho e de fase desenhadas onde são lidas (em verde quando atendem aos mínimos da especificação, em vermelho quando não), e |S| = |1/(1 + L)| e |T| = |L/(1 + L)|.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::BodeView</name>
    <message>
        <source>Bode diagram of %1</source>
        <translation>Diagrama de Bode de %1</translation>
    </message>
    <message>
        <source>No frequency analysis: %1</source>
        <translation>Sem análise em frequência: %1</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ContourBandPlot</name>
    <message>
        <source>XY contour</source>
        <translation>Contorno XY</translation>
    </message>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>The programmed contour dashed, the nominal design&apos;s traced contour solid, and the band the mismatched plant pairs trace (min–max light, 5–95 % darker); the contour error is magnified about the contour by the factor in the title.</source>
        <translation>O contorno programado tracejado, o contorno percorrido pelo projeto nominal em linha cheia e a faixa que os pares de plantas discrepantes percorrem (mín–máx claro, 5–95 % mais escuro); o erro de contorno é ampliado em torno do contorno pelo fator do título.</translation>
    </message>
    <message>
        <source>Not computed yet.</source>
        <translation>Ainda não calculado.</translation>
    </message>
    <message>
        <source>No stable plant pair: no band.</source>
        <translation>Nenhum par de plantas estável: sem faixa.</translation>
    </message>
    <message>
        <source>XY contour, error ×%1</source>
        <translation>Contorno XY, erro ×%1</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ContourControls</name>
    <message>
        <source>Ballbar</source>
        <translation>Ballbar</translation>
    </message>
    <message>
        <source>Ballbar polar view</source>
        <translation>Vista polar do ballbar</translation>
    </message>
    <message>
        <source>The ISO 230-4 circular test of the program&apos;s full circles, as a ballbar plots it</source>
        <translation>O ensaio circular ISO 230-4 dos círculos completos do programa, como um ballbar o traça</translation>
    </message>
    <message>
        <source>◀</source>
        <translation>◀</translation>
    </message>
    <message>
        <source>Previous corner</source>
        <translation>Canto anterior</translation>
    </message>
    <message>
        <source>Zoom to the previous sharp corner</source>
        <translation>Ampliar o canto vivo anterior</translation>
    </message>
    <message>
        <source>▶</source>
        <translation>▶</translation>
    </message>
    <message>
        <source>Next corner</source>
        <translation>Próximo canto</translation>
    </message>
    <message>
        <source>Zoom to the next sharp corner (after the last one: the whole path)</source>
        <translation>Ampliar o próximo canto vivo (depois do último: o percurso inteiro)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ContourPlot</name>
    <message>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>comandado</translation>
    </message>
    <message>
        <source>traced</source>
        <translation>percorrido</translation>
    </message>
    <message>
        <source>F max/min</source>
        <translation>F máx/mín</translation>
    </message>
    <message>
        <source>G (LS centre)</source>
        <translation>G (centro MQ)</translation>
    </message>
    <message>
        <source>sharp corners</source>
        <translation>cantos vivos</translation>
    </message>
    <message>
        <source>largest error</source>
        <translation>maior erro</translation>
    </message>
    <message>
        <source>XY contour: an axis could not be simulated</source>
        <translation>Contorno XY: um eixo não pôde ser simulado</translation>
    </message>
    <message>
        <source>XY contour: the program could not be run</source>
        <translation>Contorno XY: o programa não pôde ser executado</translation>
    </message>
    <message>
        <source>error × %1</source>
        <translation>erro × %1</translation>
    </message>
    <message>
        <source>independent axes, error × %1</source>
        <translation>eixos independentes, erro × %1</translation>
    </message>
    <message>
        <source>radial, after the ramp-in</source>
        <translation>radial, após a rampa de entrada</translation>
    </message>
    <message>
        <source>from the line</source>
        <translation>em relação à linha</translation>
    </message>
    <message>
        <source>Cross-coupled contour error (%1): max %2 mm, RMS %3 mm; independent axes: max %4 mm</source>
        <translation>Erro de contorno com acoplamento cruzado (%1): máx %2 mm, RMS %3 mm; eixos independentes: máx %4 mm</translation>
    </message>
    <message>
        <source>Contour error (radial, after the ramp-in): max %1 mm, RMS %2 mm</source>
        <translation>Erro de contorno (radial, após a rampa de entrada): máx %1 mm, RMS %2 mm</translation>
    </message>
    <message>
        <source>Tracking error: max |e_x| %1 mm, max |e_y| %2 mm</source>
        <translation>Erro de seguimento: máx |e_x| %1 mm, máx |e_y| %2 mm</translation>
    </message>
    <message>
        <source>programmed</source>
        <translation>programado</translation>
    </message>
    <message>
        <source>error × %1, |e| (mm) &lt; %2</source>
        <translation>erro × %1, |e| (mm) &lt; %2</translation>
    </message>
    <message>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <source>Contour error max %1, RMS %2 mm</source>
        <translation>Erro de contorno máx %1, RMS %2 mm</translation>
    </message>
    <message>
        <source>; corner %1/%2: %3 mm</source>
        <translation>; canto %1/%2: %3 mm</translation>
    </message>
    <message>
        <source>; corner %1/%2: no sample near it</source>
        <translation>; canto %1/%2: nenhuma amostra perto dele</translation>
    </message>
    <message numerus="yes">
        <source>; %n corner(s)</source>
        <translation>
            <numerusform>; %n canto</numerusform>
            <numerusform>; %n cantos</numerusform>
        </translation>
    </message>
    <message>
        <source>Cross-coupled: </source>
        <translation>Acoplamento cruzado: </translation>
    </message>
    <message>
        <source>; independent axes: max %1 mm</source>
        <translation>; eixos independentes: máx %1 mm</translation>
    </message>
    <message>
        <source>without feedforward, error × %1</source>
        <translation>sem pré-alimentação, erro × %1</translation>
    </message>
    <message>
        <source>; without feedforward: max %1 mm</source>
        <translation>; sem pré-alimentação: máx %1 mm</translation>
    </message>
    <message>
        <source>nominal</source>
        <translation>nominal</translation>
    </message>
    <message>
        <source>CW run</source>
        <translation>percurso horário</translation>
    </message>
    <message>
        <source>CCW run</source>
        <translation>percurso anti-horário</translation>
    </message>
    <message>
        <source>%1 ×%2</source>
        <translation>%1 ×%2</translation>
    </message>
    <message>
        <source>ISO 230-4 (mm): G %1, F max %2, F min %3</source>
        <translation>ISO 230-4 (mm): G %1, F máx %2, F mín %3</translation>
    </message>
    <message>
        <source>, H %1</source>
        <translation>, H %1</translation>
    </message>
    <message>
        <source>%1 without friction compensation ×%2</source>
        <translation>%1 sem compensação de atrito ×%2</translation>
    </message>
    <message>
        <source>; without friction compensation G %1</source>
        <translation>; sem compensação de atrito G %1</translation>
    </message>
    <message>
        <source>%1 with independent axes ×%2</source>
        <translation>%1 com eixos independentes ×%2</translation>
    </message>
    <message>
        <source>; independent axes G %1</source>
        <translation>; eixos independentes G %1</translation>
    </message>
    <message>
        <source>%1 without feedforward ×%2</source>
        <translation>%1 sem pré-alimentação ×%2</translation>
    </message>
    <message>
        <source>; without feedforward G %1</source>
        <translation>; sem pré-alimentação G %1</translation>
    </message>
    <message>
        <source>The XY contour: the programmed path, the traced path of both axes&apos; run, and the contour error (mm, the signed distance from each traced point to the nearest point of the path) magnified along the path normal by the &quot;error ×&quot; factor.</source>
        <translation>O contorno XY: o percurso programado, o percurso traçado pela simulação dos dois eixos e o erro de contorno (mm, a distância com sinal de cada ponto traçado ao ponto mais próximo do percurso) ampliado ao longo da normal ao percurso pelo fator &quot;erro ×&quot;.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::CouplingSweepDialog</name>
    <message>
        <source>Tune the cross-coupling by the contour error</source>
        <translation>Sintonizar o acoplamento cruzado pelo erro de contorno</translation>
    </message>
    <message>
        <source>kp values</source>
        <translation>valores de kp</translation>
    </message>
    <message>
        <source>ki values</source>
        <translation>valores de ki</translation>
    </message>
    <message>
        <source>The values of kp to try (V/mm), separated by commas; 0 and 0 is the coupling off</source>
        <translation>Os valores de kp a testar (V/mm), separados por vírgulas; 0 e 0 é o acoplamento desligado</translation>
    </message>
    <message>
        <source>The values of ki to try (V/(mm·s)), separated by commas</source>
        <translation>Os valores de ki a testar (V/(mm·s)), separados por vírgulas</translation>
    </message>
    <message>
        <source>kp (V/mm)</source>
        <translation>kp (V/mm)</translation>
    </message>
    <message>
        <source>ki (V/(mm·s))</source>
        <translation>ki (V/(mm·s))</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Executar</translation>
    </message>
    <message>
        <source>Run the sweep on the session as it is now (at most %1 pairs)</source>
        <translation>Executar a varredura na sessão como está agora (no máximo %1 pares)</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>&amp;Cancelar</translation>
    </message>
    <message>
        <source>max contour error (mm)</source>
        <translation>erro de contorno máx (mm)</translation>
    </message>
    <message>
        <source>refused: the coupled loop is unstable on a line</source>
        <translation>recusado: a malha acoplada é instável em uma linha</translation>
    </message>
    <message>
        <source>failed: the run was refused or diverged</source>
        <translation>falhou: a simulação foi recusada ou divergiu</translation>
    </message>
    <message>
        <source>not run (cancelled)</source>
        <translation>não executado (cancelado)</translation>
    </message>
    <message>
        <source>an axis reaches its limit</source>
        <translation>um eixo atinge seu limite</translation>
    </message>
    <message>
        <source>best</source>
        <translation>melhor</translation>
    </message>
    <message>
        <source>Save as PNG...</source>
        <translation>Salvar como PNG...</translation>
    </message>
    <message>
        <source>Save as PDF...</source>
        <translation>Salvar como PDF...</translation>
    </message>
    <message>
        <source>The best: %1.</source>
        <translation>O melhor: %1.</translation>
    </message>
    <message>
        <source>&amp;Apply</source>
        <translation>&amp;Aplicar</translation>
    </message>
    <message>
        <source>Set the selected cell&apos;s gains as the session&apos;s cross-coupling</source>
        <translation>Usar os ganhos da célula selecionada como o acoplamento cruzado da sessão</translation>
    </message>
    <message>
        <source>kp 0, ki 0: the coupling off (the independent axes)</source>
        <translation>kp 0, ki 0: o acoplamento desligado (eixos independentes)</translation>
    </message>
    <message>
        <source>Not run: the sweep was cancelled before it.</source>
        <translation>Não executado: a varredura foi cancelada antes.</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>Recusado: %1</translation>
    </message>
    <message>
        <source>Max contour error %1, RMS %2 (independent axes: max %3)</source>
        <translation>Erro de contorno máx %1, RMS %2 (eixos independentes: máx %3)</translation>
    </message>
    <message>
        <source>Coupled loop at its least stable direction: spectral radius %1, disk margin %2</source>
        <translation>Malha acoplada na direção menos estável: raio espectral %1, margem de disco %2</translation>
    </message>
    <message>
        <source>An axis reaches its actuator limit.</source>
        <translation>Um eixo atinge o limite do atuador.</translation>
    </message>
    <message>
        <source>Both axes stay inside their actuator limit.</source>
        <translation>Os dois eixos ficam dentro do limite do atuador.</translation>
    </message>
    <message>
        <source>Warning: %1.</source>
        <translation>Aviso: %1.</translation>
    </message>
    <message>
        <source>The best of the grid.</source>
        <translation>O melhor da grade.</translation>
    </message>
    <message>
        <source>&amp;Run again</source>
        <translation>Executar &amp;novamente</translation>
    </message>
    <message>
        <source>Computed for the session before it changed (%1). Press Run again for the session as it is.</source>
        <translation>Calculado para a sessão antes de ela mudar (%1). Clique em Executar novamente para a sessão como está.</translation>
    </message>
    <message>
        <source>Cancelling: the runs under way finish first…</source>
        <translation>Cancelando: as simulações em andamento terminam primeiro…</translation>
    </message>
    <message>
        <source>Running the contour for each pair of gains…</source>
        <translation>Simulando o contorno para cada par de ganhos…</translation>
    </message>
    <message>
        <source> The session has changed since the sweep started: its result will be for the session as it was.</source>
        <translation> A sessão mudou desde o início da varredura: o resultado será para a sessão como estava.</translation>
    </message>
    <message>
        <source>The sweep could not run: %1</source>
        <translation>A varredura não pôde ser executada: %1</translation>
    </message>
    <message>
        <source>Cancelled: %1 of %2 pairs ran.</source>
        <translation>Cancelada: %1 de %2 pares executados.</translation>
    </message>
    <message>
        <source>%1 pairs ran in %2 s.</source>
        <translation>%1 pares executados em %2 s.</translation>
    </message>
    <message>
        <source> %1 refused: the coupled loop is unstable on a line of the path.</source>
        <translation> %1 recusados: a malha acoplada é instável em uma linha do percurso.</translation>
    </message>
    <message>
        <source> %1 failed.</source>
        <translation> %1 falharam.</translation>
    </message>
    <message>
        <source> %1 drive an axis to its limit.</source>
        <translation> %1 levam um eixo ao limite.</translation>
    </message>
    <message>
        <source>Stale: the session has changed since this sweep (%1); nothing can be applied until it runs again. </source>
        <translation>Desatualizado: a sessão mudou desde esta varredura (%1); nada pode ser aplicado até que ela seja executada novamente. </translation>
    </message>
    <message>
        <source>Not run yet: press Run.</source>
        <translation>Ainda não executado: clique em Executar.</translation>
    </message>
    <message>
        <source>Independent axes (coupling off): max %1, RMS %2.</source>
        <translation>Eixos independentes (acoplamento desligado): máx %1, RMS %2.</translation>
    </message>
    <message>
        <source>Independent axes (coupling off): %1</source>
        <translation>Eixos independentes (acoplamento desligado): %1</translation>
    </message>
    <message>
        <source>Best of the pairs that ran</source>
        <translation>Melhor dos pares executados</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>Melhor</translation>
    </message>
    <message>
        <source>No pair of gains ran: no best.</source>
        <translation>Nenhum par de ganhos foi executado: não há melhor.</translation>
    </message>
    <message>
        <source>%1: the coupling off.</source>
        <translation>%1: o acoplamento desligado.</translation>
    </message>
    <message>
        <source> No pair of the grid beats the independent axes on this path.</source>
        <translation> Nenhum par da grade supera os eixos independentes neste percurso.</translation>
    </message>
    <message>
        <source>%1: %2: max %3, RMS %4</source>
        <translation>%1: %2: máx %3, RMS %4</translation>
    </message>
    <message>
        <source>, %1 times smaller than the independent axes&apos;</source>
        <translation>, %1 vezes menor que o dos eixos independentes</translation>
    </message>
    <message>
        <source>, no smaller than the independent axes&apos;</source>
        <translation>, não menor que o dos eixos independentes</translation>
    </message>
    <message>
        <source> Every pair inside the limit has a coupled loop unstable at some direction of an arc: chosen among them.</source>
        <translation> Todo par dentro do limite tem uma malha acoplada instável em alguma direção de um arco: escolhido entre eles.</translation>
    </message>
    <message>
        <source> Every pair that ran drives an axis to its limit: chosen among them.</source>
        <translation> Todo par executado leva um eixo ao limite: escolhido entre eles.</translation>
    </message>
    <message>
        <source>Selected: %1</source>
        <translation>Selecionado: %1</translation>
    </message>
    <message>
        <source>: max %1.</source>
        <translation>: máx %1.</translation>
    </message>
    <message>
        <source>: %1, nothing to apply.</source>
        <translation>: %1, nada a aplicar.</translation>
    </message>
    <message>
        <source> These are the session&apos;s gains.</source>
        <translation> Estes são os ganhos da sessão.</translation>
    </message>
    <message>
        <source>Stop the sweep; the cells run so far are shown</source>
        <translation>Interromper a varredura; as células simuladas até aqui são mostradas</translation>
    </message>
    <message>
        <source>The sweep&apos;s map: each cell one (kp, ki) pair of the cross-coupling, coloured by the program&apos;s max contour error (mm); hover a cell for its figures, click it to select it</source>
        <translation>O mapa da varredura: cada célula é um par (kp, ki) do acoplamento cruzado, colorida pelo erro de contorno máx do programa (mm); passe o mouse sobre uma célula para ver seus valores, clique para selecioná-la</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; não é um número</translation>
    </message>
</context>
<context>
    <name>xyt::ui::CrossCouplingEditor</name>
    <message>
        <source>Cross-coupling</source>
        <translation>Acoplamento cruzado</translation>
    </message>
    <message>
        <source>Proportional gain of the coupling (V per mm of estimated contour error); kp and ki 0: off</source>
        <translation>Ganho proporcional do acoplamento (V por mm de erro de contorno estimado); kp e ki 0: desligado</translation>
    </message>
    <message>
        <source>Integral gain of the coupling (V per mm·s); it stops integrating while an axis is at its limit</source>
        <translation>Ganho integral do acoplamento (V por mm·s); para de integrar enquanto um eixo está no limite</translation>
    </message>
    <message>
        <source>circular</source>
        <translation>circular</translation>
    </message>
    <message>
        <source>linear</source>
        <translation>linear</translation>
    </message>
    <message>
        <source>How the contour error is estimated from the two axis errors: the tangent line&apos;s, or the circle&apos;s with the path&apos;s curvature</source>
        <translation>Como o erro de contorno é estimado a partir dos erros dos dois eixos: o da reta tangente, ou o do círculo com a curvatura do percurso</translation>
    </message>
    <message>
        <source>kp (V/mm)</source>
        <translation>kp (V/mm)</translation>
    </message>
    <message>
        <source>ki (V/(mm·s))</source>
        <translation>ki (V/(mm·s))</translation>
    </message>
    <message>
        <source>Estimate</source>
        <translation>Estimativa</translation>
    </message>
    <message>
        <source>Tune…</source>
        <translation>Sintonizar…</translation>
    </message>
    <message>
        <source>Run the contour once for each kp and ki of a small grid and pick the gains with the smallest contour error</source>
        <translation>Simular o contorno uma vez para cada kp e ki de uma pequena grade e escolher os ganhos com o menor erro de contorno</translation>
    </message>
    <message>
        <source>Cross-coupling ●</source>
        <translation>Acoplamento cruzado ●</translation>
    </message>
    <message>
        <source>Cross-coupled contouring: kp %1 V/mm, ki %2 V/(mm·s), %3 estimate</source>
        <translation>Contorno com acoplamento cruzado: kp %1 V/mm, ki %2 V/(mm·s), estimativa %3</translation>
    </message>
    <message>
        <source>Cross-coupled contouring: off (each axis follows its own reference)</source>
        <translation>Contorno com acoplamento cruzado: desligado (cada eixo segue sua própria referência)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::DesignSpacePlot</name>
    <message>
        <source>Design space</source>
        <translation>Espaço de projeto</translation>
    </message>
    <message>
        <source>ωn (rad/s)</source>
        <translation>ωn (rad/s)</translation>
    </message>
    <message>
        <source>kp (V per model unit)</source>
        <translation>kp (V por unidade do modelo)</translation>
    </message>
    <message>
        <source>metric</source>
        <translation>métrica</translation>
    </message>
    <message>
        <source>current</source>
        <translation>atual</translation>
    </message>
    <message>
        <source>best</source>
        <translation>melhor</translation>
    </message>
    <message>
        <source>refined</source>
        <translation>refinado</translation>
    </message>
    <message>
        <source>least violating</source>
        <translation>menos violador</translation>
    </message>
    <message>
        <source>Not computed yet: set the grid and press Run.</source>
        <translation>Ainda não calculado: defina a grade e clique em Executar.</translation>
    </message>
    <message>
        <source>Show the whole grid</source>
        <translation>Mostrar a grade inteira</translation>
    </message>
    <message>
        <source>Save as PNG...</source>
        <translation>Salvar como PNG...</translation>
    </message>
    <message>
        <source>Save as PDF...</source>
        <translation>Salvar como PDF...</translation>
    </message>
    <message>
        <source>feasible region</source>
        <translation>região viável</translation>
    </message>
    <message>
        <source>Design space: each cell of the (ωn, kp) grid is one Guillemin–Truxal design run on the session&apos;s trajectory, coloured by the chosen criterion; feasible cells meet every limit of the specification. Click a cell to take its ωn and kp.</source>
        <translation>Espaço de projeto: cada célula da grade (ωn, kp) é um projeto Guillemin–Truxal simulado na trajetória da sessão, colorido pelo critério escolhido; as células viáveis atendem a todos os limites da especificação. Clique numa célula para adotar seus ωn e kp.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::DesignSpaceView</name>
    <message>
        <source>The study failed: %1</source>
        <translation>O estudo falhou: %1</translation>
    </message>
    <message>
        <source>logarithmic spacing</source>
        <translation>espaçamento logarítmico</translation>
    </message>
    <message>
        <source>Grid</source>
        <translation>Grade</translation>
    </message>
    <message>
        <source>ωn (rad/s)</source>
        <translation>ωn (rad/s)</translation>
    </message>
    <message>
        <source>kp</source>
        <translation>kp</translation>
    </message>
    <message>
        <source>logarithmic colour scale</source>
        <translation>escala de cores logarítmica</translation>
    </message>
    <message>
        <source>Choice</source>
        <translation>Escolha</translation>
    </message>
    <message>
        <source>Best design (min; max for margins)</source>
        <translation>Melhor projeto (mín; máx para margens)</translation>
    </message>
    <message>
        <source>Heat map shows</source>
        <translation>O mapa de calor mostra</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source> V</source>
        <translation> V</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source> dB</source>
        <translation> dB</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Especificação</translation>
    </message>
    <message>
        <source>settling time ≤</source>
        <translation>tempo de acomodação ≤</translation>
    </message>
    <message>
        <source>step overshoot ≤</source>
        <translation>sobressinal ao degrau ≤</translation>
    </message>
    <message>
        <source>max tracking error ≤</source>
        <translation>erro de seguimento máx ≤</translation>
    </message>
    <message>
        <source>|u| ≤ (actuator limit)</source>
        <translation>|u| ≤ (limite do atuador)</translation>
    </message>
    <message>
        <source>phase margin ≥ (0 = none)</source>
        <translation>margem de fase ≥ (0 = nenhuma)</translation>
    </message>
    <message>
        <source>gain margin ≥ (0 = none)</source>
        <translation>margem de ganho ≥ (0 = nenhuma)</translation>
    </message>
    <message>
        <source>&lt;i&gt;The session&apos;s specification, shared with the metrics panel.&lt;/i&gt;</source>
        <translation>&lt;i&gt;A especificação da sessão, compartilhada com o painel de métricas.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Executar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Set the grid and press Run to study the current axis.</source>
        <translation>Defina a grade e clique em Executar para estudar o eixo atual.</translation>
    </message>
    <message>
        <source>Relax the limits</source>
        <translation>Relaxar os limites</translation>
    </message>
    <message>
        <source>Set the specification to the smallest limits the least-violating design (▲) meets (an undoable step)</source>
        <translation>Ajustar a especificação aos menores limites que o projeto menos violador (▲) atende (um passo que pode ser desfeito)</translation>
    </message>
    <message>
        <source>Live</source>
        <translation>Ao vivo</translation>
    </message>
    <message>
        <source>Recompute the map when the plant, the trajectory or the limits change: a coarse preview at once, the full study when the inputs rest</source>
        <translation>Recalcular o mapa quando a planta, a trajetória ou os limites mudam: uma prévia grosseira na hora, o estudo completo quando as entradas param</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Configurações</translation>
    </message>
    <message>
        <source>Show or hide the grid, the choice of the best design and the specification (hidden, the map takes the whole width)</source>
        <translation>Mostrar ou ocultar a grade, a escolha do melhor projeto e a especificação (ocultos, o mapa ocupa toda a largura)</translation>
    </message>
    <message>
        <source>Hover a cell for its figures; click it to load that design. Colour: the metric (scale at the right) · unveiled, outlined: feasible · veiled: infeasible · grey: unstable or diverged.</source>
        <translation>Passe o mouse sobre uma célula para ver seus valores; clique para carregar esse projeto. Cor: a métrica (escala à direita) · sem véu, contornado: viável · com véu: inviável · cinza: instável ou divergente.</translation>
    </message>
    <message>
        <source>The design space maps a PI with its feedforward; axis %1 has D: set D to 0 to map it.</source>
        <translation>O espaço de projeto mapeia um PI com sua pré-alimentação; o eixo %1 tem D: ajuste D para 0 para mapeá-lo.</translation>
    </message>
    <message>
        <source>The design space applies to Guillemin–Truxal and PI + feedforward axes; axis %1 uses %2.</source>
        <translation>O espaço de projeto se aplica a eixos Guillemin–Truxal e PI + pré-alimentação; o eixo %1 usa %2.</translation>
    </message>
    <message>
        <source>Cannot run: %1</source>
        <translation>Não é possível executar: %1</translation>
    </message>
    <message>
        <source>Live preview of axis %1: %2 × %3 designs…</source>
        <translation>Prévia ao vivo do eixo %1: %2 × %3 projetos…</translation>
    </message>
    <message>
        <source>Studying %1 × %2 designs of axis %3…</source>
        <translation>Estudando %1 × %2 projetos do eixo %3…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Cancelando…</translation>
    </message>
    <message>
        <source>%1, axis %2</source>
        <translation>%1, eixo %2</translation>
    </message>
    <message>
        <source>Live preview (%1 × %2 designs, dt %3 s, %4 ms): the full study follows when the inputs rest.
</source>
        <translation>Prévia ao vivo (%1 × %2 projetos, dt %3 s, %4 ms): o estudo completo vem quando as entradas param.
</translation>
    </message>
    <message>
        <source>Cancelled: %1 of %2 designs computed, %3 feasible.</source>
        <translation>Cancelado: %1 de %2 projetos calculados, %3 viáveis.</translation>
    </message>
    <message>
        <source>Done: %1 designs, %2 stable, %3 feasible.</source>
        <translation>Concluído: %1 projetos, %2 estáveis, %3 viáveis.</translation>
    </message>
    <message>
        <source>
Best on the grid (★): ωn = %1 rad/s, kp = %2, %3 = %4.</source>
        <translation>
Melhor da grade (★): ωn = %1 rad/s, kp = %2, %3 = %4.</translation>
    </message>
    <message>
        <source>
Refined (◆): ωn = %1 rad/s, kp = %2, %3 = %4.</source>
        <translation>
Refinado (◆): ωn = %1 rad/s, kp = %2, %3 = %4.</translation>
    </message>
    <message>
        <source>
Click a cell to load its design.</source>
        <translation>
Clique em uma célula para carregar seu projeto.</translation>
    </message>
    <message>
        <source>
Every GT design overshoots (its reference model is type 2); relax the overshoot limit.</source>
        <translation>
Todo projeto GT tem sobressinal (seu modelo de referência é do tipo 2); relaxe o limite de sobressinal.</translation>
    </message>
    <message>
        <source>Cannot judge the study: %1</source>
        <translation>Não é possível avaliar o estudo: %1</translation>
    </message>
    <message>
        <source>This tab shows axis %1.</source>
        <translation>Esta aba mostra o eixo %1.</translation>
    </message>
    <message>
        <source>Axis %1 now uses %2: the map applies to Guillemin–Truxal and PI + feedforward axes.</source>
        <translation>O eixo %1 agora usa %2: o mapa se aplica a eixos Guillemin–Truxal e PI + pré-alimentação.</translation>
    </message>
    <message>
        <source>The plant, the trajectory or the limits the runs depend on have changed since.</source>
        <translation>A planta, a trajetória ou os limites de que as simulações dependem mudaram desde então.</translation>
    </message>
    <message>
        <source>The live map of the current design follows.</source>
        <translation>Segue o mapa ao vivo do projeto atual.</translation>
    </message>
    <message>
        <source>Press Run to study the current design.</source>
        <translation>Clique em Executar para estudar o projeto atual.</translation>
    </message>
    <message>
        <source>Map computed for %1. %2 %3</source>
        <translation>Mapa calculado para %1. %2 %3</translation>
    </message>
    <message>
        <source>The map shown is not of the session&apos;s study (computed for %1). %2</source>
        <translation>O mapa mostrado não é do estudo da sessão (calculado para %1). %2</translation>
    </message>
    <message>
        <source>Load design from the design space</source>
        <translation>Carregar projeto do espaço de projeto</translation>
    </message>
    <message>
        <source>Smallest ωn (rad/s) of the grid: the reference model&apos;s natural frequency of the first row of designs</source>
        <translation>Menor ωn (rad/s) da grade: a frequência natural do modelo de referência da primeira linha de projetos</translation>
    </message>
    <message>
        <source>Largest ωn (rad/s) of the grid</source>
        <translation>Maior ωn (rad/s) da grade</translation>
    </message>
    <message>
        <source>Number of ωn values of the grid (rows); each cell is one design run on the session&apos;s trajectory</source>
        <translation>Número de valores de ωn da grade (linhas); cada célula é um projeto simulado na trajetória da sessão</translation>
    </message>
    <message>
        <source>Smallest proportional gain kp (V per model unit) of the grid</source>
        <translation>Menor ganho proporcional kp (V por unidade do modelo) da grade</translation>
    </message>
    <message>
        <source>Largest proportional gain kp (V per model unit) of the grid</source>
        <translation>Maior ganho proporcional kp (V por unidade do modelo) da grade</translation>
    </message>
    <message>
        <source>Number of kp values of the grid (columns)</source>
        <translation>Número de valores de kp da grade (colunas)</translation>
    </message>
    <message>
        <source>Space the ωn and kp values evenly on a logarithmic scale (else linearly between the bounds)</source>
        <translation>Espaçar os valores de ωn e kp uniformemente em escala logarítmica (senão, linearmente entre os limites)</translation>
    </message>
    <message>
        <source>The figure that picks the best feasible design: minimized (ITAE, max |e|, RMSE, max |u|, settle time) or maximized (the margins)</source>
        <translation>O valor que escolhe o melhor projeto viável: minimizado (ITAE, |e| máx, RMSE, |u| máx, tempo de acomodação) ou maximizado (as margens)</translation>
    </message>
    <message>
        <source>The figure the heat map&apos;s colours show for each design of the grid</source>
        <translation>O valor que as cores do mapa de calor mostram para cada projeto da grade</translation>
    </message>
    <message>
        <source>Colour the heat map by the logarithm of the figure (its values often span decades)</source>
        <translation>Colorir o mapa de calor pelo logaritmo do valor (seus valores costumam abranger várias décadas)</translation>
    </message>
    <message>
        <source>Maximum settling time (s, 2 % band) of the closed loop&apos;s unit step</source>
        <translation>Tempo de acomodação máximo (s, faixa de 2 %) do degrau unitário da malha fechada</translation>
    </message>
    <message>
        <source>Maximum overshoot (%) of the closed loop&apos;s unit step</source>
        <translation>Sobressinal máximo (%) do degrau unitário da malha fechada</translation>
    </message>
    <message>
        <source>Maximum tracking error max |e| as a percentage of the travel</source>
        <translation>Erro de seguimento máximo |e| máx como porcentagem do curso</translation>
    </message>
    <message>
        <source>Actuator limit umax (V): a design whose run asks for more is infeasible; the session&apos;s |u| limit</source>
        <translation>Limite do atuador umax (V): um projeto cuja simulação exige mais é inviável; o limite de |u| da sessão</translation>
    </message>
    <message>
        <source>Minimum phase margin (°) of the loop, 180° + arg L(jωc); 0: none</source>
        <translation>Margem de fase mínima (°) da malha, 180° + arg L(jωc); 0: nenhuma</translation>
    </message>
    <message>
        <source>Minimum gain margin (dB) of the loop, −20 log10 |L(jω180)|; 0: none</source>
        <translation>Margem de ganho mínima (dB) da malha, −20 log10 |L(jω180)|; 0: nenhuma</translation>
    </message>
    <message>
        <source>Run the study: every design of the grid on the session&apos;s trajectory at its dt, judged against the specification</source>
        <translation>Executar o estudo: cada projeto da grade na trajetória da sessão com o seu dt, avaliado frente à especificação</translation>
    </message>
    <message>
        <source>Stop the study; the designs computed so far are shown</source>
        <translation>Interromper o estudo; os projetos calculados até aqui são mostrados</translation>
    </message>
</context>
<context>
    <name>xyt::ui::EnvelopePlot</name>
    <message>
        <source>Envelope</source>
        <translation>Envoltória</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>min–max</source>
        <translation>mín–máx</translation>
    </message>
    <message>
        <source>5–95 %</source>
        <translation>5–95 %</translation>
    </message>
    <message>
        <source>median</source>
        <translation>mediana</translation>
    </message>
    <message>
        <source>nominal</source>
        <translation>nominal</translation>
    </message>
    <message>
        <source>Not computed yet.</source>
        <translation>Ainda não calculado.</translation>
    </message>
    <message>
        <source>No stable plant: no envelope.</source>
        <translation>Nenhuma planta estável: sem envoltória.</translation>
    </message>
    <message>
        <source>Envelope of the perturbed plants&apos; runs: the range (min to max over the stable plants) of the chosen signal (error or output in mm, command in V) around the nominal run, against time (s).</source>
        <translation>Envoltória das simulações das plantas perturbadas: a faixa (do mínimo ao máximo sobre as plantas estáveis) do sinal escolhido (erro ou saída em mm, comando em V) em torno da simulação nominal, em função do tempo (s).</translation>
    </message>
</context>
<context>
    <name>xyt::ui::EquationsPanel</name>
    <message>
        <source>Design equations</source>
        <translation>Equações de projeto</translation>
    </message>
    <message>
        <source>&lt;b&gt;Axis %1&lt;/b&gt;: %2: %3</source>
        <translation>&lt;b&gt;Eixo %1&lt;/b&gt;: %2: %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;Axis %1 — pole placement + ZPETC&lt;/b&gt; (T&lt;sub&gt;s&lt;/sub&gt; = %2 s)&lt;br&gt;</source>
        <translation>&lt;b&gt;Eixo %1 — alocação de polos + ZPETC&lt;/b&gt; (T&lt;sub&gt;s&lt;/sub&gt; = %2 s)&lt;br&gt;</translation>
    </message>
    <message>
        <source>A F + B G = T (Diophantine, Patrick, Ishak and Adnan Eq. 8)&lt;br&gt;</source>
        <translation>A F + B G = T (diofantina, Patrick, Ishak e Adnan Eq. 8)&lt;br&gt;</translation>
    </message>
    <message>
        <source>A = %1&lt;br&gt;B = %2&lt;br&gt;T = %3&lt;br&gt;</source>
        <translation>A = %1&lt;br&gt;B = %2&lt;br&gt;T = %3&lt;br&gt;</translation>
    </message>
    <message>
        <source>F = %1&lt;br&gt;G = %2&lt;br&gt;</source>
        <translation>F = %1&lt;br&gt;G = %2&lt;br&gt;</translation>
    </message>
    <message>
        <source>K&lt;sub&gt;f&lt;/sub&gt; = T(1)/B(1) = %1, residual %2&lt;br&gt;</source>
        <translation>K&lt;sub&gt;f&lt;/sub&gt; = T(1)/B(1) = %1, resíduo %2&lt;br&gt;</translation>
    </message>
    <message>
        <source>control law: F u = K&lt;sub&gt;f&lt;/sub&gt; w − G y&lt;br&gt;</source>
        <translation>lei de controle: F u = K&lt;sub&gt;f&lt;/sub&gt; w − G y&lt;br&gt;</translation>
    </message>
    <message>
        <source>ZPETC: w(k) = N/D · r(k + %1), [B&lt;sup&gt;−&lt;/sup&gt;(1)]&lt;sup&gt;2&lt;/sup&gt; = %2&lt;br&gt;</source>
        <translation>ZPETC: w(k) = N/D · r(k + %1), [B&lt;sup&gt;−&lt;/sup&gt;(1)]&lt;sup&gt;2&lt;/sup&gt; = %2&lt;br&gt;</translation>
    </message>
    <message>
        <source>N = %1&lt;br&gt;D = %2</source>
        <translation>N = %1&lt;br&gt;D = %2</translation>
    </message>
    <message>
        <source>no feedforward: w = r</source>
        <translation>sem pré-alimentação: w = r</translation>
    </message>
    <message>
        <source>&lt;b&gt;Axis %1 — %2&lt;/b&gt;&lt;br&gt;</source>
        <translation>&lt;b&gt;Eixo %1 — %2&lt;/b&gt;&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Axis %1 — Guillemin–Truxal PI&lt;/b&gt; (ω&lt;sub&gt;n&lt;/sub&gt; = %2 rad/s, k&lt;sub&gt;p&lt;/sub&gt; = %3)&lt;br&gt;</source>
        <translation>&lt;b&gt;Eixo %1 — PI de Guillemin–Truxal&lt;/b&gt; (ω&lt;sub&gt;n&lt;/sub&gt; = %2 rad/s, k&lt;sub&gt;p&lt;/sub&gt; = %3)&lt;br&gt;</translation>
    </message>
    <message>
        <source>f&lt;sub&gt;1&lt;/sub&gt; = a&lt;sub&gt;1&lt;/sub&gt;/ω&lt;sub&gt;n&lt;/sub&gt; = %1&lt;br&gt;</source>
        <translation>f&lt;sub&gt;1&lt;/sub&gt; = a&lt;sub&gt;1&lt;/sub&gt;/ω&lt;sub&gt;n&lt;/sub&gt; = %1&lt;br&gt;</translation>
    </message>
    <message>
        <source>f&lt;sub&gt;2&lt;/sub&gt; = a&lt;sub&gt;2&lt;/sub&gt;/ω&lt;sub&gt;n&lt;/sub&gt;&lt;sup&gt;2&lt;/sup&gt; = %1&lt;br&gt;</source>
        <translation>f&lt;sub&gt;2&lt;/sub&gt; = a&lt;sub&gt;2&lt;/sub&gt;/ω&lt;sub&gt;n&lt;/sub&gt;&lt;sup&gt;2&lt;/sup&gt; = %1&lt;br&gt;</translation>
    </message>
    <message>
        <source>f&lt;sub&gt;3&lt;/sub&gt; = k&lt;sub&gt;p&lt;/sub&gt;k&lt;sub&gt;0&lt;/sub&gt;/ω&lt;sub&gt;n&lt;/sub&gt;&lt;sup&gt;3&lt;/sup&gt; = %1&lt;br&gt;</source>
        <translation>f&lt;sub&gt;3&lt;/sub&gt; = k&lt;sub&gt;p&lt;/sub&gt;k&lt;sub&gt;0&lt;/sub&gt;/ω&lt;sub&gt;n&lt;/sub&gt;&lt;sup&gt;3&lt;/sup&gt; = %1&lt;br&gt;</translation>
    </message>
    <message>
        <source>ψ&lt;sub&gt;1&lt;/sub&gt; = ω&lt;sub&gt;n&lt;/sub&gt;&lt;sup&gt;4&lt;/sup&gt;/(k&lt;sub&gt;p&lt;/sub&gt;k&lt;sub&gt;0&lt;/sub&gt;) = %1, ψ&lt;sub&gt;2&lt;/sub&gt; = %2&lt;br&gt;</source>
        <translation>ψ&lt;sub&gt;1&lt;/sub&gt; = ω&lt;sub&gt;n&lt;/sub&gt;&lt;sup&gt;4&lt;/sup&gt;/(k&lt;sub&gt;p&lt;/sub&gt;k&lt;sub&gt;0&lt;/sub&gt;) = %1, ψ&lt;sub&gt;2&lt;/sub&gt; = %2&lt;br&gt;</translation>
    </message>
    <message>
        <source>k&lt;sub&gt;i&lt;/sub&gt; = k&lt;sub&gt;p&lt;/sub&gt;ψ&lt;sub&gt;1&lt;/sub&gt; = %1&lt;br&gt;</source>
        <translation>k&lt;sub&gt;i&lt;/sub&gt; = k&lt;sub&gt;p&lt;/sub&gt;ψ&lt;sub&gt;1&lt;/sub&gt; = %1&lt;br&gt;</translation>
    </message>
    <message>
        <source>G&lt;sub&gt;c&lt;/sub&gt;(s) = %1 + %2/s&lt;br&gt;</source>
        <translation>G&lt;sub&gt;c&lt;/sub&gt;(s) = %1 + %2/s&lt;br&gt;</translation>
    </message>
    <message>
        <source>G&lt;sub&gt;R&lt;/sub&gt;(s) = (%1) / (%2)</source>
        <translation>G&lt;sub&gt;R&lt;/sub&gt;(s) = (%1) / (%2)</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;span style=&apos;color:#d32f2f&apos;&gt;&lt;b&gt;The closed loop is unstable.&lt;/b&gt;&lt;/span&gt;</source>
        <translation>&lt;br&gt;&lt;span style=&apos;color:#d32f2f&apos;&gt;&lt;b&gt;A malha fechada é instável.&lt;/b&gt;&lt;/span&gt;</translation>
    </message>
</context>
<context>
    <name>xyt::ui::FlexibleModeEditor</name>
    <message>
        <source>Flexible mode and notch</source>
        <translation>Modo flexível e notch</translation>
    </message>
    <message>
        <source>Mode (Hz)</source>
        <translation>Modo (Hz)</translation>
    </message>
    <message>
        <source>The table&apos;s resonance fr above the rigid plant (belt, screw, gantry); 0: a rigid table. The design is made on the rigid plant; every run and analysis has the mode</source>
        <translation>A ressonância fr da mesa acima da planta rígida (correia, fuso, pórtico); 0: mesa rígida. O projeto é feito na planta rígida; toda simulação e análise inclui o modo</translation>
    </message>
    <message>
        <source>Mode damping</source>
        <translation>Amortecimento do modo</translation>
    </message>
    <message>
        <source>Damping ratio of the resonance, in [0, 1); its peak stands 1/(2 ζ) above the rigid plant</source>
        <translation>Coeficiente de amortecimento da ressonância, em [0, 1); seu pico fica 1/(2 ζ) acima da planta rígida</translation>
    </message>
    <message>
        <source>Anti-resonance (Hz)</source>
        <translation>Antirressonância (Hz)</translation>
    </message>
    <message>
        <source>A two-mass model measured at the motor: its anti-resonance below fr; 0: the resonant pair fr² / (s² + 2 ζ fr s + fr²) alone</source>
        <translation>Um modelo de duas massas medido no motor: sua antirressonância abaixo de fr; 0: só o par ressonante fr² / (s² + 2 ζ fr s + fr²)</translation>
    </message>
    <message>
        <source>Anti-res. damping</source>
        <translation>Amort. antirress.</translation>
    </message>
    <message>
        <source>Damping ratio of the anti-resonance, in [0, 1)</source>
        <translation>Coeficiente de amortecimento da antirressonância, em [0, 1)</translation>
    </message>
    <message>
        <source>Notch centre (Hz)</source>
        <translation>Centro do notch (Hz)</translation>
    </message>
    <message>
        <source>Notch on the error the PI reads, (s² + 2 ζz w0 s + w0²) / (s² + 2 ζp w0 s + w0²); 0: none. Digital: bilinear, prewarped at the centre, below the controller&apos;s Nyquist frequency</source>
        <translation>Filtro notch no erro que o PI lê, (s² + 2 ζz w0 s + w0²) / (s² + 2 ζp w0 s + w0²); 0: nenhum. Digital: bilinear, com pré-distorção no centro, abaixo da frequência de Nyquist do controlador</translation>
    </message>
    <message>
        <source>Notch width (Hz)</source>
        <translation>Largura do notch (Hz)</translation>
    </message>
    <message>
        <source>Bandwidth of the notch&apos;s pole pair: 2 ζp f0</source>
        <translation>Largura de banda do par de polos do notch: 2 ζp f0</translation>
    </message>
    <message>
        <source>Notch depth (dB)</source>
        <translation>Profundidade do notch (dB)</translation>
    </message>
    <message>
        <source>Attenuation at the centre, in (0, 120] dB</source>
        <translation>Atenuação no centro, em (0, 120] dB</translation>
    </message>
    <message>
        <source>Notch at the mode</source>
        <translation>Notch no modo</translation>
    </message>
    <message>
        <source>Centre on the mode, as deep as its peak (6 to 40 dB) and four half-power bandwidths wide</source>
        <translation>Centrado no modo, tão profundo quanto seu pico (6 a 40 dB) e com quatro larguras de banda de meia potência</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>Input shaper on both axes&apos; reference: ZV, ZVD, ZVDD (Singer and Seering), MZV (Klipper), EI and the multi-hump EI (Singhose et al.)</source>
        <translation>Modelador de entrada na referência dos dois eixos: ZV, ZVD, ZVDD (Singer e Seering), MZV (Klipper), EI e o EI de várias corcovas (Singhose et al.)</translation>
    </message>
    <message>
        <source>Input shaper</source>
        <translation>Modelador de entrada</translation>
    </message>
    <message>
        <source>Shaper frequency (Hz)</source>
        <translation>Frequência do modelador (Hz)</translation>
    </message>
    <message>
        <source>The mode the shaper is designed for; acts on the reference at the trajectory&apos;s step, so the controller&apos;s period does not limit it</source>
        <translation>O modo para o qual o modelador é projetado; atua na referência no passo da trajetória, então o período do controlador não o limita</translation>
    </message>
    <message>
        <source>Shaper damping</source>
        <translation>Amortecimento do modelador</translation>
    </message>
    <message>
        <source>The damping ratio it is designed for, [0, 1)</source>
        <translation>O coeficiente de amortecimento para o qual é projetado, [0, 1)</translation>
    </message>
    <message>
        <source>Shaper at the mode</source>
        <translation>Modelador no modo</translation>
    </message>
    <message>
        <source>Design the shaper for this axis&apos; mode (ZV unless a type is chosen)</source>
        <translation>Projetar o modelador para o modo deste eixo (ZV, a menos que um tipo seja escolhido)</translation>
    </message>
    <message>
        <source>Recommend</source>
        <translation>Recomendar</translation>
    </message>
    <message>
        <source>Klipper&apos;s choice of shaper and frequency for this mode: the least vibration left for the smoothing, and the acceleration it allows</source>
        <translation>A escolha do Klipper de modelador e frequência para este modo: a menor vibração restante para a suavização, e a aceleração que ela permite</translation>
    </message>
    <message>
        <source>From a log…</source>
        <translation>De um registro…</translation>
    </message>
    <message>
        <source>Klipper&apos;s choice from an accelerometer log (#time,accel_x,accel_y,accel_z), as calibrate_shaper.py makes it</source>
        <translation>A escolha do Klipper a partir de um registro de acelerômetro (#time,accel_x,accel_y,accel_z), como o calibrate_shaper.py a faz</translation>
    </message>
    <message>
        <source>the %1 Hz mode</source>
        <translation>o modo de %1 Hz</translation>
    </message>
    <message>
        <source>No recommendation: %1</source>
        <translation>Sem recomendação: %1</translation>
    </message>
    <message>
        <source>Accelerometer log</source>
        <translation>Registro de acelerômetro</translation>
    </message>
    <message>
        <source>Klipper CSV (*.csv);;All files (*)</source>
        <translation>CSV do Klipper (*.csv);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>no flexible mode to tune the shaper to</source>
        <translation>nenhum modo flexível para sintonizar o modelador</translation>
    </message>
    <message>
        <source>A pole-placement axis&apos; ARX model holds whatever mode its data showed: identify it from a log that excites the mode.</source>
        <translation>O modelo ARX de um eixo por alocação de polos contém o modo que seus dados mostraram: identifique-o a partir de um registro que excite o modo.</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s pid has no notch stage: the notch is offered on Guillemin–Truxal axes.</source>
        <translation>O pid do LinuxCNC não tem estágio notch: o notch é oferecido em eixos Guillemin–Truxal.</translation>
    </message>
    <message>
        <source>Klipper&apos;s choice for %1: %2 at %3 Hz, %4 % vibration left, smoothing %5 mm, max accel %6 mm/s²</source>
        <translation>Escolha do Klipper para %1: %2 em %3 Hz, %4 % de vibração restante, suavização %5 mm, acel. máx %6 mm/s²</translation>
    </message>
    <message>
        <source>mode %1 Hz, ζ %2</source>
        <translation>modo %1 Hz, ζ %2</translation>
    </message>
    <message>
        <source>notch %1 Hz, %2 dB</source>
        <translation>notch %1 Hz, %2 dB</translation>
    </message>
    <message>
        <source>%1 shaper at %2 Hz</source>
        <translation>modelador %1 em %2 Hz</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Mode ●</source>
        <translation>Modo ●</translation>
    </message>
    <message>
        <source>Flexible mode and notch: none (the rigid table)</source>
        <translation>Modo flexível e notch: nenhum (mesa rígida)</translation>
    </message>
    <message>
        <source>Flexible mode and notch: %1</source>
        <translation>Modo flexível e notch: %1</translation>
    </message>
</context>
<context>
    <name>xyt::ui::FrictionCurveDialog</name>
    <message>
        <source>Friction curve from a jog log</source>
        <translation>Curva de atrito de um registro de jog</translation>
    </message>
    <message>
        <source>&amp;Open log…</source>
        <translation>&amp;Abrir registro…</translation>
    </message>
    <message>
        <source>No log: run xytune-cli excite --signal jog, or log jogs from the machine (time, reference, position, command)</source>
        <translation>Nenhum registro: execute xytune-cli excite --signal jog, ou registre jogs da máquina (tempo, referência, posição, comando)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Tempo (s)</translation>
    </message>
    <message>
        <source>Reference (mm)</source>
        <translation>Referência (mm)</translation>
    </message>
    <message>
        <source>Position (mm)</source>
        <translation>Posição (mm)</translation>
    </message>
    <message>
        <source>Command (V)</source>
        <translation>Comando (V)</translation>
    </message>
    <message>
        <source>velocity (mm/s)</source>
        <translation>velocidade (mm/s)</translation>
    </message>
    <message>
        <source>steady command (V)</source>
        <translation>comando em regime (V)</translation>
    </message>
    <message>
        <source>jogs (mean ± 1 sd)</source>
        <translation>jogs (média ± 1 dp)</translation>
    </message>
    <message>
        <source>fitted curve</source>
        <translation>curva ajustada</translation>
    </message>
    <message>
        <source>&amp;Use for the current axis</source>
        <translation>&amp;Usar para o eixo atual</translation>
    </message>
    <message>
        <source>Open a jog log</source>
        <translation>Abrir um registro de jog</translation>
    </message>
    <message>
        <source>Experiment logs (*.csv *.tsv *.txt *.lvm *.mat);;All files (*)</source>
        <translation>Registros de ensaio (*.csv *.tsv *.txt *.lvm *.mat);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>%1: %2 columns, %3 rows</source>
        <translation>%1: %2 colunas, %3 linhas</translation>
    </message>
    <message>
        <source>time</source>
        <translation>tempo</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>referência</translation>
    </message>
    <message>
        <source>position</source>
        <translation>posição</translation>
    </message>
    <message>
        <source>command</source>
        <translation>comando</translation>
    </message>
    <message>
        <source>Coulomb %1; slope %2 (the model&apos;s own a2/k0: %3 V per mm/s, so %4 beyond it)</source>
        <translation>Coulomb %1; inclinação %2 (o a2/k0 do próprio modelo: %3 V por mm/s, portanto %4 além dele)</translation>
    </message>
    <message>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <source>V per mm/s</source>
        <translation>V por mm/s</translation>
    </message>
    <message>
        <source>; static %1, Stribeck velocity %2</source>
        <translation>; estático %1, velocidade de Stribeck %2</translation>
    </message>
    <message>
        <source>mm/s</source>
        <translation>mm/s</translation>
    </message>
    <message>
        <source>. %1 jogs, residual sd %2 V.</source>
        <translation>. %1 jogs, dp do resíduo %2 V.</translation>
    </message>
    <message>
        <source>The log&apos;s column of the %1</source>
        <translation>A coluna do registro para %1</translation>
    </message>
    <message>
        <source>The Stribeck curve: each jog&apos;s steady command (V, mean ± one standard deviation over its cruise) against its velocity (mm/s), and the fitted friction curve sign(v)(Fc + (Fs − Fc) exp(−(v/vs)²)) + bv v</source>
        <translation>A curva de Stribeck: o comando em regime de cada jog (V, média ± um desvio-padrão no trecho de velocidade constante) em função da sua velocidade (mm/s), e a curva de atrito ajustada sign(v)(Fc + (Fs − Fc) exp(−(v/vs)²)) + bv v</translation>
    </message>
    <message>
        <source>Read a jog log (CSV with time, reference, position and command columns) and estimate the friction levels</source>
        <translation>Ler um registro de jog (CSV com colunas de tempo, referência, posição e comando) e estimar os níveis de atrito</translation>
    </message>
    <message>
        <source>Set the estimated levels as the current axis&apos; table friction (one undoable step)</source>
        <translation>Definir os níveis estimados como o atrito da mesa do eixo atual (um passo que pode ser desfeito)</translation>
    </message>
    <message>
        <source>choose its column</source>
        <translation>escolha a sua coluna</translation>
    </message>
</context>
<context>
    <name>xyt::ui::FrictionEditor</name>
    <message>
        <source>Friction and backlash</source>
        <translation>Atrito e folga</translation>
    </message>
    <message>
        <source>Coulomb (V)</source>
        <translation>Coulomb (V)</translation>
    </message>
    <message>
        <source>Coulomb friction Fc in volts of equivalent command: what the axis needs beyond its linear model to keep sliding</source>
        <translation>Atrito de Coulomb Fc em volts de comando equivalente: o que o eixo precisa além de seu modelo linear para continuar deslizando</translation>
    </message>
    <message>
        <source>Static (V)</source>
        <translation>Estático (V)</translation>
    </message>
    <message>
        <source>Static (breakaway) level Fs in volts; 0 takes the Coulomb level (no Stribeck dip)</source>
        <translation>Nível estático (de desprendimento) Fs em volts; 0 usa o nível de Coulomb (sem a queda de Stribeck)</translation>
    </message>
    <message>
        <source>Stribeck velocity (mm/s)</source>
        <translation>Velocidade de Stribeck (mm/s)</translation>
    </message>
    <message>
        <source>vs of f(v) = sign(v) (Fc + (Fs - Fc) exp(-(v/vs)²)): how fast the friction falls from Fs to Fc</source>
        <translation>vs de f(v) = sign(v) (Fc + (Fs - Fc) exp(-(v/vs)²)): quão rápido o atrito cai de Fs para Fc</translation>
    </message>
    <message>
        <source>Viscous (V per mm/s)</source>
        <translation>Viscoso (V por mm/s)</translation>
    </message>
    <message>
        <source>Viscous friction beyond the model&apos;s own damping (a2/k0 already holds it): 0 by default</source>
        <translation>Atrito viscoso além do amortecimento do próprio modelo (a2/k0 já o contém): 0 por padrão</translation>
    </message>
    <message>
        <source>Backlash (mm)</source>
        <translation>Folga (mm)</translation>
    </message>
    <message>
        <source>Play between motor and table: the table stays while the motor crosses the gap</source>
        <translation>Folga entre motor e mesa: a mesa fica parada enquanto o motor atravessa a folga</translation>
    </message>
    <message>
        <source>Amplifier deadband (V)</source>
        <translation>Zona morta do amplificador (V)</translation>
    </message>
    <message>
        <source>|u| below it gives no output; beyond it the amplifier gives u - d sign(u)</source>
        <translation>|u| abaixo dela não dá saída; acima dela o amplificador dá u - d sign(u)</translation>
    </message>
    <message>
        <source>the faster pole</source>
        <translation>o polo mais rápido</translation>
    </message>
    <message>
        <source>the slower pole</source>
        <translation>o polo mais lento</translation>
    </message>
    <message>
        <source>Which root of s² + a1 s + a2 is the drive&apos;s electrical lag; the other is the moving mass, where the friction acts</source>
        <translation>Qual raiz de s² + a1 s + a2 é o atraso elétrico do acionamento; a outra é a massa em movimento, onde o atrito atua</translation>
    </message>
    <message>
        <source>Electrical lag</source>
        <translation>Atraso elétrico</translation>
    </message>
    <message>
        <source>Compensation (%)</source>
        <translation>Compensação (%)</translation>
    </message>
    <message>
        <source>Friction feedforward from the reference velocity, in percent of the Coulomb and viscous levels above (0: none)</source>
        <translation>Pré-alimentação de atrito a partir da velocidade de referência, em porcentagem dos níveis de Coulomb e viscoso acima (0: nenhuma)</translation>
    </message>
    <message>
        <source>Compensation band (mm/s)</source>
        <translation>Faixa de compensação (mm/s)</translation>
    </message>
    <message>
        <source>The Coulomb term ramps linearly across |v| &lt; band instead of jumping at v = 0</source>
        <translation>O termo de Coulomb varia linearmente em |v| &lt; faixa em vez de saltar em v = 0</translation>
    </message>
    <message>
        <source>A pole-placement axis&apos; ARX model has no moving mass: it takes the Coulomb level and the amplifier deadband, as a dead zone of its input</source>
        <translation>O modelo ARX de um eixo por alocação de polos não tem massa em movimento: ele usa o nível de Coulomb e a zona morta do amplificador, como uma zona morta da sua entrada</translation>
    </message>
    <message>
        <source>Coulomb %1 V</source>
        <translation>Coulomb %1 V</translation>
    </message>
    <message>
        <source>backlash %1 mm</source>
        <translation>folga %1 mm</translation>
    </message>
    <message>
        <source>deadband %1 V</source>
        <translation>zona morta %1 V</translation>
    </message>
    <message>
        <source>viscous</source>
        <translation>viscoso</translation>
    </message>
    <message>
        <source>compensated %1 %</source>
        <translation>compensado %1 %</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Atrito</translation>
    </message>
    <message>
        <source>Friction ●</source>
        <translation>Atrito ●</translation>
    </message>
    <message>
        <source>Friction and backlash: none (the linear table)</source>
        <translation>Atrito e folga: nenhum (mesa linear)</translation>
    </message>
    <message>
        <source>Friction and backlash: %1</source>
        <translation>Atrito e folga: %1</translation>
    </message>
</context>
<context>
    <name>xyt::ui::HistogramPlot</name>
    <message>
        <source>Distribution</source>
        <translation>Distribuição</translation>
    </message>
    <message>
        <source>plants</source>
        <translation>plantas</translation>
    </message>
    <message>
        <source>limit</source>
        <translation>limite</translation>
    </message>
    <message>
        <source>nominal</source>
        <translation>nominal</translation>
    </message>
    <message>
        <source>Not computed yet.</source>
        <translation>Ainda não calculado.</translation>
    </message>
    <message>
        <source>No stable plant: no distribution.</source>
        <translation>Nenhuma planta estável: sem distribuição.</translation>
    </message>
    <message>
        <source>Histogram of the chosen figure (RMSE or max |e| in mm, max |u| in V) over the stable perturbed plants, with the specification&apos;s limit drawn.</source>
        <translation>Histograma do valor escolhido (RMSE ou |e| máx em mm, |u| máx em V) sobre as plantas perturbadas estáveis, com o limite da especificação desenhado.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::IdentificationWindow</name>
    <message>
        <source>Identify a model from data</source>
        <translation>Identificar um modelo a partir de dados</translation>
    </message>
    <message>
        <source>Fit a model to see it here.</source>
        <translation>Ajuste um modelo para vê-lo aqui.</translation>
    </message>
    <message>
        <source>Load data…</source>
        <translation>Carregar dados…</translation>
    </message>
    <message>
        <source>(no file)</source>
        <translation>(nenhum arquivo)</translation>
    </message>
    <message>
        <source>Validation data…</source>
        <translation>Dados de validação…</translation>
    </message>
    <message>
        <source>(none: judged on the estimation data)</source>
        <translation>(nenhum: avaliado nos dados de estimação)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Range of the record to use; 0 to 0 uses all of it</source>
        <translation>Intervalo do registro a usar; 0 a 0 usa o registro inteiro</translation>
    </message>
    <message>
        <source>Remove trends</source>
        <translation>Remover tendências</translation>
    </message>
    <message>
        <source>Keep every n-th sample after an anti-alias filter (1: all)</source>
        <translation>Manter uma amostra a cada n após um filtro anti-aliasing (1: todas)</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Dados</translation>
    </message>
    <message>
        <source>Input (V):</source>
        <translation>Entrada (V):</translation>
    </message>
    <message>
        <source>Output:</source>
        <translation>Saída:</translation>
    </message>
    <message>
        <source>Output unit:</source>
        <translation>Unidade da saída:</translation>
    </message>
    <message>
        <source>Time:</source>
        <translation>Tempo:</translation>
    </message>
    <message>
        <source>Ts:</source>
        <translation>Ts:</translation>
    </message>
    <message>
        <source>to</source>
        <translation>a</translation>
    </message>
    <message>
        <source>Range:</source>
        <translation>Intervalo:</translation>
    </message>
    <message>
        <source>Decimate:</source>
        <translation>Decimar:</translation>
    </message>
    <message>
        <source>ARX</source>
        <translation>ARX</translation>
    </message>
    <message>
        <source>OE</source>
        <translation>OE</translation>
    </message>
    <message>
        <source>BJ</source>
        <translation>BJ</translation>
    </message>
    <message>
        <source>GT3 continuous</source>
        <translation>GT3 contínuo</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modelo</translation>
    </message>
    <message>
        <source>Structure:</source>
        <translation>Estrutura:</translation>
    </message>
    <message>
        <source>Max iterations:</source>
        <translation>Iterações máx:</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Ajustar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Load a record of the axis (input in V, output position) to begin.</source>
        <translation>Carregue um registro do eixo (entrada em V, saída posição) para começar.</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Fit % est</source>
        <translation>Ajuste % est</translation>
    </message>
    <message>
        <source>Fit % val</source>
        <translation>Ajuste % val</translation>
    </message>
    <message>
        <source>AIC</source>
        <translation>AIC</translation>
    </message>
    <message>
        <source>Residuals</source>
        <translation>Resíduos</translation>
    </message>
    <message>
        <source>NMP</source>
        <translation>FNM</translation>
    </message>
    <message>
        <source>The selected model&apos;s parameters, each ± one standard deviation</source>
        <translation>Os parâmetros do modelo selecionado, cada um ± um desvio padrão</translation>
    </message>
    <message>
        <source>Use for axis X</source>
        <translation>Usar para o eixo X</translation>
    </message>
    <message>
        <source>Use for axis Y</source>
        <translation>Usar para o eixo Y</translation>
    </message>
    <message>
        <source>Response → X</source>
        <translation>Resposta → X</translation>
    </message>
    <message>
        <source>Response → Y</source>
        <translation>Resposta → Y</translation>
    </message>
    <message>
        <source>Welch&apos;s estimate of y/u (Hann window, 50 % overlap) with its coherence, drawn over the axis&apos; model in the Vibration view</source>
        <translation>Estimativa de Welch de y/u (janela de Hann, 50 % de sobreposição) com sua coerência, desenhada sobre o modelo do eixo na vista Vibração</translation>
    </message>
    <message>
        <source>Load experiment data</source>
        <translation>Carregar dados de ensaio</translation>
    </message>
    <message>
        <source>Experiment files (*.csv *.tsv *.txt *.lvm *.mat);;All files (*)</source>
        <translation>Arquivos de ensaio (*.csv *.tsv *.txt *.lvm *.mat);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>Load validation data</source>
        <translation>Carregar dados de validação</translation>
    </message>
    <message>
        <source>measured y</source>
        <translation>y medido</translation>
    </message>
    <message>
        <source>simulated ŷ (model)</source>
        <translation>ŷ simulado (modelo)</translation>
    </message>
    <message>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posição (mm)</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Saída</translation>
    </message>
    <message>
        <source>residual autocorr.</source>
        <translation>autocorr. do resíduo</translation>
    </message>
    <message>
        <source>lag (samples)</source>
        <translation>atraso (amostras)</translation>
    </message>
    <message>
        <source>input–residual corr.</source>
        <translation>corr. entrada–resíduo</translation>
    </message>
    <message>
        <source>Poles and zeros</source>
        <translation>Polos e zeros</translation>
    </message>
    <message>
        <source>%1: %2 columns, %3 rows%4. Pick the columns and press Fit.</source>
        <translation>%1: %2 colunas, %3 linhas%4. Escolha as colunas e clique em Ajustar.</translation>
    </message>
    <message>
        <source>, Ts = %1 s stated by the file</source>
        <translation>, Ts = %1 s informado pelo arquivo</translation>
    </message>
    <message>
        <source>The candidates fitted to the previous file were cleared.</source>
        <translation>Os candidatos ajustados ao arquivo anterior foram removidos.</translation>
    </message>
    <message>
        <source>These columns cannot be used yet: %1</source>
        <translation>Estas colunas ainda não podem ser usadas: %1</translation>
    </message>
    <message>
        <source>No data loaded.</source>
        <translation>Nenhum dado carregado.</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Não é possível ler %1: %2</translation>
    </message>
    <message>
        <source>Validation data: %1 (%2 rows).</source>
        <translation>Dados de validação: %1 (%2 linhas).</translation>
    </message>
    <message>
        <source>No model: the data could not be used.</source>
        <translation>Nenhum modelo: os dados não puderam ser usados.</translation>
    </message>
    <message>
        <source>Cannot fit: %1</source>
        <translation>Não é possível ajustar: %1</translation>
    </message>
    <message>
        <source>%1: the first sample %2 mm was subtracted (the plant starts at rest at 0); the fit estimates where the table stood</source>
        <translation>%1: a primeira amostra %2 mm foi subtraída (a planta parte do repouso em 0); o ajuste estima onde a mesa estava</translation>
    </message>
    <message>
        <source>Fitting %1 to %2 samples…</source>
        <translation>Ajustando %1 a %2 amostras…</translation>
    </message>
    <message>
        <source>No frequency response: load a record first</source>
        <translation>Sem resposta em frequência: carregue um registro primeiro</translation>
    </message>
    <message>
        <source>Frequency response of %1: %2 averages of %3 samples, drawn in the Vibration view of axis %4</source>
        <translation>Resposta em frequência de %1: %2 médias de %3 amostras, desenhada na vista Vibração do eixo %4</translation>
    </message>
    <message>
        <source>No frequency response: %1</source>
        <translation>Sem resposta em frequência: %1</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Cancelando…</translation>
    </message>
    <message>
        <source>No model: the fit failed.</source>
        <translation>Nenhum modelo: o ajuste falhou.</translation>
    </message>
    <message>
        <source>The fit failed: %1</source>
        <translation>O ajuste falhou: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source> (%1)</source>
        <translation> (%1)</translation>
    </message>
    <message>
        <source>Estimated initial position: %1 mm</source>
        <translation>Posição inicial estimada: %1 mm</translation>
    </message>
    <message>
        <source>No estimate: %1</source>
        <translation>Sem estimativa: %1</translation>
    </message>
    <message>
        <source>GT3</source>
        <translation>GT3</translation>
    </message>
    <message>
        <source>pass</source>
        <translation>aprovado</translation>
    </message>
    <message>
        <source>fail</source>
        <translation>reprovado</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sim</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
    </message>
    <message>
        <source>Pole-zero map (z-plane)</source>
        <translation>Mapa de polos e zeros (plano z)</translation>
    </message>
    <message>
        <source>Select a candidate to see it here.</source>
        <translation>Selecione um candidato para vê-lo aqui.</translation>
    </message>
    <message>
        <source>Parameters (± 1 SD): %1</source>
        <translation>Parâmetros (± 1 DP): %1</translation>
    </message>
    <message>
        <source>residual autocorr. (%1)</source>
        <translation>autocorr. do resíduo (%1)</translation>
    </message>
    <message>
        <source>input–residual corr. (%1)</source>
        <translation>corr. entrada–resíduo (%1)</translation>
    </message>
    <message>
        <source>Pole-zero map (z-plane): a zero outside the unit circle (NMP)</source>
        <translation>Mapa de polos e zeros (plano z): um zero fora do círculo unitário (FNM)</translation>
    </message>
    <message>
        <source>A pole at z = 1: the model integrates, as the position of a motor axis does (every other pole is inside the unit circle).</source>
        <translation>Um polo em z = 1: o modelo integra, como a posição de um eixo motorizado (todos os outros polos estão dentro do círculo unitário).</translation>
    </message>
    <message>
        <source>A pole is on or outside the unit circle: the model is unstable.</source>
        <translation>Um polo está sobre ou fora do círculo unitário: o modelo é instável.</translation>
    </message>
    <message>
        <source>Pick the columns and press Fit.</source>
        <translation>Escolha as colunas e clique em Ajustar.</translation>
    </message>
    <message>
        <source>The record: %1 samples, %2 s to %3 s, Ts = %4 s (no model yet)</source>
        <translation>O registro: %1 amostras, %2 s a %3 s, Ts = %4 s (ainda sem modelo)</translation>
    </message>
    <message>
        <source>The record cannot be drawn: %1</source>
        <translation>O registro não pode ser desenhado: %1</translation>
    </message>
    <message>
        <source>Use the identified %1 for axis %2</source>
        <translation>Usar o %1 identificado para o eixo %2</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Axis %1 now uses the identified %2 (Edit › Undo restores the previous plant).</source>
        <translation>O eixo %1 agora usa o %2 identificado (Editar › Desfazer restaura a planta anterior).</translation>
    </message>
    <message>
        <source>Cannot use this model: %1</source>
        <translation>Não é possível usar este modelo: %1</translation>
    </message>
    <message>
        <source>(sample time)</source>
        <translation>(período de amostragem)</translation>
    </message>
    <message>
        <source>Remove a straight line fitted by least squares from the input and the output before the fit (else their means)</source>
        <translation>Remover da entrada e da saída uma reta ajustada por mínimos quadrados antes do ajuste (senão, suas médias)</translation>
    </message>
    <message>
        <source>Read a logged experiment: CSV/TSV, LabVIEW .lvm or MATLAB .mat, with the input in V and the position</source>
        <translation>Ler um ensaio registrado: CSV/TSV, LabVIEW .lvm ou MATLAB .mat, com a entrada em V e a posição</translation>
    </message>
    <message>
        <source>A second record of the same axis on which the candidates&apos; fit is judged (else on the estimation data)</source>
        <translation>Um segundo registro do mesmo eixo no qual o ajuste dos candidatos é avaliado (senão, nos dados de estimação)</translation>
    </message>
    <message>
        <source>The column of the command u (V) sent to the amplifier</source>
        <translation>A coluna do comando u (V) enviado ao amplificador</translation>
    </message>
    <message>
        <source>The column of the measured position y</source>
        <translation>A coluna da posição medida y</translation>
    </message>
    <message>
        <source>The column of the time (s), or none: the sample time Ts below</source>
        <translation>A coluna do tempo (s), ou nenhuma: o período de amostragem Ts abaixo</translation>
    </message>
    <message>
        <source>Sample time Ts (s) of the record when it has no time column</source>
        <translation>Período de amostragem Ts (s) do registro quando ele não tem coluna de tempo</translation>
    </message>
    <message>
        <source>The unit of the output column: mm, or m (converted to mm)</source>
        <translation>A unidade da coluna de saída: mm, ou m (convertido para mm)</translation>
    </message>
    <message>
        <source>ARX: A y = B u + e by least squares; OE: y = B/F u + e and BJ: y = B/F u + C/D e by prediction error (Levenberg–Marquardt); GT3: Braga et al.&apos;s k0/(s³ + a1 s² + a2 s) fitted to the output</source>
        <translation>ARX: A y = B u + e por mínimos quadrados; OE: y = B/F u + e e BJ: y = B/F u + C/D e por erro de predição (Levenberg–Marquardt); GT3: o k0/(s³ + a1 s² + a2 s) de Braga et al. ajustado à saída</translation>
    </message>
    <message>
        <source>Order %1 of the model: na, nb, nc, nd, nf the numbers of coefficients of A, B, C, D, F; nk the input delay in samples</source>
        <translation>Ordem %1 do modelo: na, nb, nc, nd, nf são os números de coeficientes de A, B, C, D, F; nk é o atraso da entrada em amostras</translation>
    </message>
    <message>
        <source>The most Levenberg–Marquardt iterations of an OE, BJ or GT3 fit before it stops with the best estimate so far</source>
        <translation>O número máximo de iterações de Levenberg–Marquardt de um ajuste OE, BJ ou GT3 antes que ele pare com a melhor estimativa até então</translation>
    </message>
    <message>
        <source>Estimate the model of the chosen structure and orders; it is added to the candidates with its fit, AIC and residual tests</source>
        <translation>Estimar o modelo com a estrutura e as ordens escolhidas; ele é adicionado aos candidatos com seu ajuste, AIC e testes de resíduos</translation>
    </message>
    <message>
        <source>Stop the fit running</source>
        <translation>Interromper o ajuste em andamento</translation>
    </message>
    <message>
        <source>Make the selected model axis X&apos;s plant (an undoable step): GT3 as the Guillemin–Truxal plant, ARX/OE/BJ as the pole-placement model</source>
        <translation>Tornar o modelo selecionado a planta do eixo X (um passo que pode ser desfeito): GT3 como planta de Guillemin–Truxal, ARX/OE/BJ como modelo da alocação de polos</translation>
    </message>
    <message>
        <source>Make the selected model axis Y&apos;s plant (an undoable step)</source>
        <translation>Tornar o modelo selecionado a planta do eixo Y (um passo que pode ser desfeito)</translation>
    </message>
    <message>
        <source>The measured output y (mm) against time (s) and the selected model&apos;s simulated output ŷ from the same input</source>
        <translation>A saída medida y (mm) em função do tempo (s) e a saída simulada ŷ do modelo selecionado a partir da mesma entrada</translation>
    </message>
    <message>
        <source>The residuals&apos; autocorrelation and their cross-correlation with the input against the lag, with the 99 % confidence band of white, independent residuals</source>
        <translation>A autocorrelação dos resíduos e sua correlação cruzada com a entrada em função do atraso, com a faixa de confiança de 99 % de resíduos brancos e independentes</translation>
    </message>
    <message>
        <source>the end must be after the start (0 to 0 uses the whole record)</source>
        <translation>o fim deve ser depois do início (0 a 0 usa o registro inteiro)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ImplementationEditor</name>
    <message>
        <source>Computation delay: the command computed at sample k is applied at k + delay</source>
        <translation>Atraso de cálculo: o comando calculado na amostra k é aplicado em k + atraso</translation>
    </message>
    <message>
        <source>Encoder resolution in mm per count; 0 = ideal (no quantization)</source>
        <translation>Resolução do encoder em mm por contagem; 0 = ideal (sem quantização)</translation>
    </message>
    <message>
        <source>DAC resolution over ±umax; 0 = ideal</source>
        <translation>Resolução do DAC em ±umax; 0 = ideal</translation>
    </message>
    <message>
        <source>clamping</source>
        <translation>grampeamento</translation>
    </message>
    <message>
        <source>back-calculation</source>
        <translation>retrocálculo</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>Anti-windup</source>
        <translation>Anti-windup</translation>
    </message>
    <message>
        <source>How the digital PI&apos;s integrator is kept from winding up while u is clipped: clamping (conditional integration) is what ships</source>
        <translation>Como o integrador do PI digital é impedido de acumular enquanto u está limitado: o grampeamento (integração condicional) é o que se usa na prática</translation>
    </message>
    <message>
        <source>Back-calculation tracking time Tt (s); 0 = Ti = kp/ki</source>
        <translation>Tempo de rastreamento Tt do retrocálculo (s); 0 = Ti = kp/ki</translation>
    </message>
    <message>
        <source>Delay (samples)</source>
        <translation>Atraso (amostras)</translation>
    </message>
    <message>
        <source>Encoder (mm/count)</source>
        <translation>Encoder (mm/contagem)</translation>
    </message>
    <message>
        <source>DAC bits</source>
        <translation>Bits do DAC</translation>
    </message>
    <message>
        <source>Tracking time (s)</source>
        <translation>Tempo de rastreamento (s)</translation>
    </message>
    <message>
        <source>must be an integer in 0..32 (0: ideal DAC)</source>
        <translation>deve ser um inteiro em 0..32 (0: DAC ideal)</translation>
    </message>
    <message>
        <source>must be an integer in 0..%1</source>
        <translation>deve ser um inteiro em 0..%1</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (s; 0: Tt = Ti = kp/ki)</source>
        <translation>deve ser &gt;= 0 (s; 0: Tt = Ti = kp/ki)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::MainWindow</name>
    <message>
        <source>XY Tune</source>
        <translation>XY Tune</translation>
    </message>
    <message>
        <source>Picking a gain sets kp and ωn of a Guillemin–Truxal axis, or P, I and D of a PID; this axis uses %1.</source>
        <translation>Escolher um ganho define kp e ωn de um eixo Guillemin–Truxal, ou P, I e D de um PID; este eixo usa %1.</translation>
    </message>
    <message>
        <source>Loop gain %1 applied: P, I and D scaled</source>
        <translation>Ganho de malha %1 aplicado: P, I e D escalados</translation>
    </message>
    <message>
        <source>Loop gain %1 applied: kp and ωn scaled</source>
        <translation>Ganho de malha %1 aplicado: kp e ωn escalados</translation>
    </message>
    <message>
        <source>Loop gain %1 of the design before the drag applied</source>
        <translation>Ganho de malha %1 do projeto anterior ao arraste aplicado</translation>
    </message>
    <message>
        <source>Dragging a pole sets the loop gain of a Guillemin–Truxal axis or a PID.</source>
        <translation>Arrastar um polo define o ganho de malha de um eixo Guillemin–Truxal ou de um PID.</translation>
    </message>
    <message>
        <source>The zero stays: %1</source>
        <translation>O zero permanece: %1</translation>
    </message>
    <message>
        <source>Zero moved to %1 %2 %3j</source>
        <translation>Zero movido para %1 %2 %3j</translation>
    </message>
    <message>
        <source>&amp;Root locus</source>
        <translation>&amp;Lugar das raízes</translation>
    </message>
    <message>
        <source>P&amp;arameter locus</source>
        <translation>Lugar do p&amp;arâmetro</translation>
    </message>
    <message>
        <source>&amp;Pole-zero</source>
        <translation>&amp;Polos e zeros</translation>
    </message>
    <message>
        <source>&amp;Bode</source>
        <translation>&amp;Bode</translation>
    </message>
    <message>
        <source>&amp;Nyquist</source>
        <translation>&amp;Nyquist</translation>
    </message>
    <message>
        <source>&amp;Vibration</source>
        <translation>&amp;Vibração</translation>
    </message>
    <message>
        <source>sweep ωn (kp fixed)</source>
        <translation>varrer ωn (kp fixo)</translation>
    </message>
    <message>
        <source>sweep kp (ωn fixed)</source>
        <translation>varrer kp (ωn fixo)</translation>
    </message>
    <message>
        <source>Swept parameter</source>
        <translation>Parâmetro varrido</translation>
    </message>
    <message>
        <source>&amp;Time</source>
        <translation>&amp;Tempo</translation>
    </message>
    <message>
        <source>Time response: the trajectory, the tracking error and the control signal</source>
        <translation>Resposta no tempo: a trajetória, o erro de seguimento e o sinal de controle</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Degrau</translation>
    </message>
    <message>
        <source>Step response of each axis against the specification&apos;s envelope</source>
        <translation>Resposta ao degrau de cada eixo contra a envoltória da especificação</translation>
    </message>
    <message>
        <source>&amp;XY contour</source>
        <translation>Contorno &amp;XY</translation>
    </message>
    <message>
        <source>error × </source>
        <translation>erro × </translation>
    </message>
    <message>
        <source>Contour error magnification</source>
        <translation>Ampliação do erro de contorno</translation>
    </message>
    <message>
        <source>Magnification of the contour error in the XY plot (as a ballbar plot)</source>
        <translation>Ampliação do erro de contorno no gráfico XY (como em um gráfico de ballbar)</translation>
    </message>
    <message>
        <source>&amp;Design space</source>
        <translation>&amp;Espaço de projeto</translation>
    </message>
    <message>
        <source>R&amp;obustness</source>
        <translation>R&amp;obustez</translation>
    </message>
    <message>
        <source>Metrics</source>
        <translation>Métricas</translation>
    </message>
    <message>
        <source>Equations</source>
        <translation>Equações</translation>
    </message>
    <message>
        <source>Trajectory</source>
        <translation>Trajetória</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Eixo %1</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Eixo</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>Projeto</translation>
    </message>
    <message>
        <source>Design method</source>
        <translation>Método de projeto</translation>
    </message>
    <message>
        <source>Guillemin–Truxal PI (continuous)</source>
        <translation>PI de Guillemin–Truxal (contínuo)</translation>
    </message>
    <message>
        <source>Pole placement + ZPETC (discrete)</source>
        <translation>Alocação de polos + ZPETC (discreto)</translation>
    </message>
    <message>
        <source>ω&amp;n</source>
        <translation>ω&amp;n</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>k&amp;p</source>
        <translation>k&amp;p</translation>
    </message>
    <message>
        <source>V/m</source>
        <translation>V/m</translation>
    </message>
    <message>
        <source>Axis %1 now uses %2; Edit › Undo switches back</source>
        <translation>O eixo %1 agora usa %2; Editar › Desfazer volta atrás</translation>
    </message>
    <message>
        <source>Axis %1 now uses pole placement on Patrick, Ishak and Adnan&apos;s ARX model (the pole-placement plant, not the Guillemin–Truxal one); Edit › Undo switches back</source>
        <translation>O eixo %1 agora usa alocação de polos no modelo ARX de Patrick, Ishak e Adnan (a planta da alocação de polos, não a de Guillemin–Truxal); Editar › Desfazer volta atrás</translation>
    </message>
    <message>
        <source>Axis %1 now uses pole placement on its ARX model; Edit › Undo switches back</source>
        <translation>O eixo %1 agora usa alocação de polos em seu modelo ARX; Editar › Desfazer volta atrás</translation>
    </message>
    <message>
        <source>Axis %1 now uses the Guillemin–Truxal PI on its continuous plant; Edit › Undo switches back</source>
        <translation>O eixo %1 agora usa o PI de Guillemin–Truxal em sua planta contínua; Editar › Desfazer volta atrás</translation>
    </message>
    <message>
        <source>Actuator and digital controller</source>
        <translation>Atuador e controlador digital</translation>
    </message>
    <message>
        <source>|u| limit (V)</source>
        <translation>Limite de |u| (V)</translation>
    </message>
    <message>
        <source>Tustin</source>
        <translation>Tustin</translation>
    </message>
    <message>
        <source>backward Euler</source>
        <translation>Euler regressivo</translation>
    </message>
    <message>
        <source>PI discretization</source>
        <translation>Discretização do PI</translation>
    </message>
    <message>
        <source>Controller Ts (s)</source>
        <translation>Ts do controlador (s)</translation>
    </message>
    <message>
        <source>Digital implementation settings</source>
        <translation>Configurações da implementação digital</translation>
    </message>
    <message>
        <source>Delay, encoder, DAC and anti-windup of the digital controller</source>
        <translation>Atraso, encoder, DAC e anti-windup do controlador digital</translation>
    </message>
    <message>
        <source>Load preset %1</source>
        <translation>Carregar predefinição %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>Sa&amp;ir</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Desfazer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Refazer</translation>
    </message>
    <message>
        <source>&amp;Design</source>
        <translation>&amp;Projeto</translation>
    </message>
    <message>
        <source>&amp;Store snapshot...</source>
        <translation>&amp;Guardar instantâneo...</translation>
    </message>
    <message>
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <source>Store snapshot</source>
        <translation>Guardar instantâneo</translation>
    </message>
    <message>
        <source>Name of the snapshot:</source>
        <translation>Nome do instantâneo:</translation>
    </message>
    <message>
        <source>design %1</source>
        <translation>projeto %1</translation>
    </message>
    <message>
        <source>&amp;Compare designs...</source>
        <translation>&amp;Comparar projetos...</translation>
    </message>
    <message>
        <source>&amp;Identify from data...</source>
        <translation>&amp;Identificar a partir de dados...</translation>
    </message>
    <message>
        <source>F&amp;riction curve from a jog log...</source>
        <translation>Curva de a&amp;trito de um registro de jog...</translation>
    </message>
    <message>
        <source>Add &amp;feedforward from the model</source>
        <translation>Adicionar pré-&amp;alimentação do modelo</translation>
    </message>
    <message>
        <source>Feedforward of %1 from the model</source>
        <translation>Pré-alimentação de %1 a partir do modelo</translation>
    </message>
    <message>
        <source>No feedforward from the model</source>
        <translation>Sem pré-alimentação a partir do modelo</translation>
    </message>
    <message>
        <source>The plant&apos;s exact inverse as FF1, FF2, FF3: a Guillemin–Truxal axis becomes the same PI in LinuxCNC&apos;s units on the PID + feedforward method</source>
        <translation>A inversa exata da planta como FF1, FF2, FF3: um eixo Guillemin–Truxal passa a ser o mesmo PI nas unidades do LinuxCNC no método PID + pré-alimentação</translation>
    </message>
    <message>
        <source>&amp;Tune the PID...</source>
        <translation>&amp;Sintonizar o PID...</translation>
    </message>
    <message>
        <source>PI or PID gains from a crossover and phase margin, or from a simulated relay experiment (PID + feedforward axes)</source>
        <translation>Ganhos PI ou PID a partir de uma frequência de cruzamento e margem de fase, ou de um ensaio de relé simulado (eixos PID + pré-alimentação)</translation>
    </message>
    <message>
        <source>&amp;Overlay snapshot</source>
        <translation>S&amp;obrepor instantâneo</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>E&amp;xibir</translation>
    </message>
    <message>
        <source>Show the &amp;digital implementation</source>
        <translation>Mostrar a implementação &amp;digital</translation>
    </message>
    <message>
        <source>Overlay the loop as the firmware runs it on the time plots</source>
        <translation>Sobrepor a malha como o firmware a executa nos gráficos no tempo</translation>
    </message>
    <message>
        <source>Pole-zero map of the digital loop (&amp;z-plane)</source>
        <translation>Mapa de polos e zeros da malha digital (plano &amp;z)</translation>
    </message>
    <message>
        <source>&amp;Reset plot views</source>
        <translation>&amp;Restaurar as vistas dos gráficos</translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Aj&amp;uda</translation>
    </message>
    <message>
        <source>&amp;About XY Tune</source>
        <translation>&amp;Sobre o XY Tune</translation>
    </message>
    <message>
        <source>About XY Tune</source>
        <translation>Sobre o XY Tune</translation>
    </message>
    <message>
        <source>&lt;b&gt;XY Tune&lt;/b&gt; %1&lt;br&gt;Tuning workbench for XY coordinate-table position controllers.&lt;br&gt;GPL-3.0-or-later.</source>
        <translation>&lt;b&gt;XY Tune&lt;/b&gt; %1&lt;br&gt;Bancada de sintonia de controladores de posição de mesas de coordenadas XY.&lt;br&gt;GPL-3.0-or-later.</translation>
    </message>
    <message>
        <source>On its lines the coupled loop is stable: spectral radius %1 at worst (direction %2°)</source>
        <translation>Em suas linhas a malha acoplada é estável: raio espectral %1 no pior caso (direção %2°)</translation>
    </message>
    <message>
        <source>Frozen at each direction the coupled loop is stable: spectral radius %1 at worst (direction %2°)</source>
        <translation>Congelada em cada direção, a malha acoplada é estável: raio espectral %1 no pior caso (direção %2°)</translation>
    </message>
    <message>
        <source>, beside a pole at z = 1 the contour never sees (the coupling&apos;s integral and the axes&apos; integrators sharing a constant voltage)</source>
        <translation>, além de um polo em z = 1 que o contorno nunca vê (a integral do acoplamento e os integradores dos eixos dividindo uma tensão constante)</translation>
    </message>
    <message>
        <source>; disk margin %1: ±%2 dB, ±%3°</source>
        <translation>; margem de disco %1: ±%2 dB, ±%3°</translation>
    </message>
    <message>
        <source>; at the %1 input: phase margin %2°</source>
        <translation>; na entrada %1: margem de fase %2°</translation>
    </message>
    <message>
        <source>Contour error max %1 mm (independent axes %2 mm).</source>
        <translation>Erro de contorno máx %1 mm (eixos independentes %2 mm).</translation>
    </message>
    <message>
        <source>Contour error max %1 mm (independent axes %2 mm). </source>
        <translation>Erro de contorno máx %1 mm (eixos independentes %2 mm). </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>clamp</source>
        <translation>grampeamento</translation>
    </message>
    <message>
        <source>back-calc.</source>
        <translation>retrocálc.</translation>
    </message>
    <message>
        <source>no anti-windup</source>
        <translation>sem anti-windup</translation>
    </message>
    <message>
        <source>Implementation: %1, %2%3</source>
        <translation>Implementação: %1, %2%3</translation>
    </message>
    <message>
        <source>quantized</source>
        <translation>quantizada</translation>
    </message>
    <message>
        <source>ideal</source>
        <translation>ideal</translation>
    </message>
    <message>
        <source>, delay %1</source>
        <translation>, atraso %1</translation>
    </message>
    <message>
        <source>Encoder %1, DAC %2, anti-windup %3, computation delay %4 sample(s). Click to edit.</source>
        <translation>Encoder %1, DAC %2, anti-windup %3, atraso de cálculo %4 amostra(s). Clique para editar.</translation>
    </message>
    <message>
        <source>%1 mm/count</source>
        <translation>%1 mm/contagem</translation>
    </message>
    <message>
        <source>%1 bits</source>
        <translation>%1 bits</translation>
    </message>
    <message>
        <source>%1: invalid (%2)  </source>
        <translation>%1: inválido (%2)  </translation>
    </message>
    <message>
        <source>%1: UNSTABLE  </source>
        <translation>%1: INSTÁVEL  </translation>
    </message>
    <message>
        <source>%1: stable  </source>
        <translation>%1: estável  </translation>
    </message>
    <message>
        <source>| updated in %1 ms</source>
        <translation>| atualizado em %1 ms</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Nenhum</translation>
    </message>
    <message>
        <source>%1[*] — XY Tune</source>
        <translation>%1[*] — XY Tune</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sem título</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>&amp;System language</source>
        <translation>Idioma do &amp;sistema</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>The language changes when XY Tune is started again.</source>
        <translation>O idioma muda quando o XY Tune for iniciado novamente.</translation>
    </message>
    <message>
        <source>The parameter the parameter locus sweeps over its slider&apos;s range, the other held at the design&apos;s value</source>
        <translation>O parâmetro que o lugar do parâmetro varre na faixa do seu controle deslizante, com o outro mantido no valor do projeto</translation>
    </message>
    <message>
        <source>How the current axis is controlled: Guillemin–Truxal PI (Braga et al.), pole placement + ZPETC (Patrick, Ishak and Adnan) or LinuxCNC&apos;s PID with command feedforward</source>
        <translation>Como o eixo atual é controlado: PI de Guillemin–Truxal (Braga et al.), alocação de polos + ZPETC (Patrick, Ishak e Adnan) ou o PID do LinuxCNC com pré-alimentação do comando</translation>
    </message>
    <message>
        <source>ωn (rad/s): the natural frequency of the 4th-order reference model G_R(s); the PI follows as f3 = kp k0/ωn³, ki = ωn⁴/k0 (Braga et al. Eq. 11–18)</source>
        <translation>ωn (rad/s): a frequência natural do modelo de referência de 4ª ordem G_R(s); o PI decorre como f3 = kp k0/ωn³, ki = ωn⁴/k0 (Braga et al., Eq. 11–18)</translation>
    </message>
    <message>
        <source>kp (V per model unit): the PI&apos;s proportional gain; with ωn it sets ki = kp ψ1 = ωn⁴/k0 and the reference model&apos;s f3 = kp k0/ωn³</source>
        <translation>kp (V por unidade do modelo): o ganho proporcional do PI; junto com ωn ele define ki = kp ψ1 = ωn⁴/k0 e o f3 = kp k0/ωn³ do modelo de referência</translation>
    </message>
    <message>
        <source>Actuator limit umax (V): every run clips the command to ±umax, and the anti-windup acts at it</source>
        <translation>Limite do atuador umax (V): toda simulação limita o comando a ±umax, e o anti-windup atua nesse limite</translation>
    </message>
    <message>
        <source>Controller sample time Ts (s) of the digital PI or PID: the digital implementation runs and the exports are at it</source>
        <translation>Período de amostragem Ts (s) do controlador do PI ou PID digital: a implementação digital é simulada e as exportações são feitas nesse período</translation>
    </message>
    <message>
        <source>How the PI kp + ki/s is discretized at the controller sample time: Tustin s = (2/Ts)(z − 1)/(z + 1), or backward Euler s = (z − 1)/(z Ts)</source>
        <translation>Como o PI kp + ki/s é discretizado no período de amostragem do controlador: Tustin s = (2/Ts)(z − 1)/(z + 1), ou Euler regressivo s = (z − 1)/(z Ts)</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>&amp;Guia do usuário</translation>
    </message>
    <message>
        <source>&amp;Tutorials...</source>
        <translation>&amp;Tutoriais...</translation>
    </message>
    <message>
        <source>&amp;Command-line reference</source>
        <translation>Referência da &amp;linha de comando</translation>
    </message>
</context>
<context>
    <name>xyt::ui::MethodParameterEditor</name>
    <message>
        <source>This method has no settings.</source>
        <translation>Este método não tem configurações.</translation>
    </message>
    <message>
        <source>%1 (%2 .. %3 %4)</source>
        <translation>%1 (%2 .. %3 %4)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Set %1 of %2 to %3</source>
        <translation>Definir %1 de %2 como %3</translation>
    </message>
</context>
<context>
    <name>xyt::ui::MetricsPanel</name>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>spec</source>
        <translation>espec.</translation>
    </message>
    <message>
        <source>RMSE (mm)</source>
        <translation>RMSE (mm)</translation>
    </message>
    <message>
        <source>max |e| (mm)</source>
        <translation>máx |e| (mm)</translation>
    </message>
    <message>
        <source>max |e| (%)</source>
        <translation>máx |e| (%)</translation>
    </message>
    <message>
        <source>max |u| (V)</source>
        <translation>máx |u| (V)</translation>
    </message>
    <message>
        <source>saturated (s)</source>
        <translation>saturado (s)</translation>
    </message>
    <message>
        <source>ITAE (mm·s²)</source>
        <translation>ITAE (mm·s²)</translation>
    </message>
    <message>
        <source>ZPETC gain (%)</source>
        <translation>ganho ZPETC (%)</translation>
    </message>
    <message>
        <source>settle time (s)</source>
        <translation>t. acomodação (s)</translation>
    </message>
    <message>
        <source>final e (mm)</source>
        <translation>e final (mm)</translation>
    </message>
    <message>
        <source>overrun (mm)</source>
        <translation>excesso (mm)</translation>
    </message>
    <message>
        <source>settling 2 % (s)</source>
        <translation>acomod. 2 % (s)</translation>
    </message>
    <message>
        <source>overshoot (%)</source>
        <translation>sobressinal (%)</translation>
    </message>
    <message>
        <source>min ζ (z-plane)</source>
        <translation>ζ mín (plano z)</translation>
    </message>
    <message>
        <source>gain margin (dB)</source>
        <translation>marg. ganho (dB)</translation>
    </message>
    <message>
        <source>phase margin (°)</source>
        <translation>marg. fase (°)</translation>
    </message>
    <message>
        <source>delay margin (s)</source>
        <translation>marg. atraso (s)</translation>
    </message>
    <message>
        <source>Ms = max |S|</source>
        <translation>Ms = máx |S|</translation>
    </message>
    <message>
        <source>Tracking the trajectory</source>
        <translation>Seguimento da trajetória</translation>
    </message>
    <message>
        <source>Move and settle (point-to-point)</source>
        <translation>Movimento e acomodação</translation>
    </message>
    <message>
        <source>Unit step, as each axis runs</source>
        <translation>Degrau unitário de cada eixo</translation>
    </message>
    <message>
        <source>Digital implementation</source>
        <translation>Implementação digital</translation>
    </message>
    <message>
        <source>Loop margins (open loop L)</source>
        <translation>Margens (malha aberta L)</translation>
    </message>
    <message>
        <source>Guillemin–Truxal: the step of G_R(s), the continuous closed loop. Pole placement: the step previewed through the ZPETC feedforward and the loop when ZPETC is on, else the step of the feedback loop Kf·B/T alone.</source>
        <translation>Guillemin–Truxal: o degrau de G_R(s), a malha fechada contínua. Alocação de polos: o degrau pré-visto pela pré-alimentação ZPETC e pela malha quando o ZPETC está ligado; senão, o degrau só da malha de realimentação Kf·B/T.</translation>
    </message>
    <message>
        <source>The controller at its sample time with the hold, the encoder and DAC quantization, the limit, the anti-windup and the delay of the Digital implementation settings. An amber figure differs from the design&apos;s above by more than 5 %.</source>
        <translation>O controlador no seu período de amostragem com o retentor, a quantização do encoder e do DAC, o limite, o anti-windup e o atraso das configurações da implementação digital. Um valor em âmbar difere do projeto acima em mais de 5 %.</translation>
    </message>
    <message>
        <source>Metrics</source>
        <translation>Métricas</translation>
    </message>
    <message>
        <source>Why the specification fails</source>
        <translation>Por que a especificação falha</translation>
    </message>
    <message>
        <source>Relax the limits</source>
        <translation>Relaxar os limites</translation>
    </message>
    <message>
        <source>Contour error figures</source>
        <translation>Valores do erro de contorno</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Avisos</translation>
    </message>
    <message>
        <source>Maximum settling time (2 % band) of the unit step</source>
        <translation>Tempo de acomodação máximo (faixa de 2 %) do degrau unitário</translation>
    </message>
    <message>
        <source>Maximum |e| as a percentage of the travel</source>
        <translation>|e| máximo como porcentagem do curso</translation>
    </message>
    <message>
        <source>Maximum settle time after the end (tf) of a point-to-point move</source>
        <translation>Tempo de acomodação máximo após o fim (tf) de um movimento ponto a ponto</translation>
    </message>
    <message>
        <source>In-position window of a point-to-point move: |e| ≤ this (mm)</source>
        <translation>Janela de posição de um movimento ponto a ponto: |e| ≤ este valor (mm)</translation>
    </message>
    <message>
        <source>Minimum phase margin (PM, degrees) of the loop; 0 = none (the paper states none). 45–60° is the usual rule.</source>
        <translation>Margem de fase mínima (MF, graus) da malha; 0 = nenhuma (o artigo não define). 45–60° é a regra usual.</translation>
    </message>
    <message>
        <source>Minimum gain margin (GM, dB) of the loop; 0 = none. 6 dB is the usual rule.</source>
        <translation>Margem de ganho mínima (MG, dB) da malha; 0 = nenhuma. 6 dB é a regra usual.</translation>
    </message>
    <message>
        <source>Every Guillemin–Truxal design overshoots a little on a step (its reference model is type 2), so 0 % fails them all.</source>
        <translation>Todo projeto Guillemin–Truxal tem um pequeno sobressinal ao degrau (seu modelo de referência é do tipo 2), então 0 % reprova todos.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Specification&lt;/b&gt;</source>
        <translation>&lt;b&gt;Especificação&lt;/b&gt;</translation>
    </message>
    <message>
        <source>The limits of the spec column above: each figure is judged against them</source>
        <translation>Os limites da coluna espec. acima: cada valor é avaliado em relação a eles</translation>
    </message>
    <message>
        <source>settling ≤ s</source>
        <translation>acomod. 2 % ≤ s</translation>
    </message>
    <message>
        <source>overshoot ≤ %</source>
        <translation>sobressinal ≤ %</translation>
    </message>
    <message>
        <source>max |e| ≤ %</source>
        <translation>máx |e| ≤ %</translation>
    </message>
    <message>
        <source>settle ≤ s</source>
        <translation>t. acomodação ≤ s</translation>
    </message>
    <message>
        <source>window mm</source>
        <translation>janela mm</translation>
    </message>
    <message>
        <source>PM ≥ °</source>
        <translation>MF ≥ °</translation>
    </message>
    <message>
        <source>GM ≥ dB</source>
        <translation>MG ≥ dB</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>n/d</translation>
    </message>
    <message>
        <source>the closed loop is unstable: not a robustness measure</source>
        <translation>a malha fechada é instável: não é uma medida de robustez</translation>
    </message>
    <message>
        <source>at %1 rad/s (factor %2)</source>
        <translation>em %1 rad/s (fator %2)</translation>
    </message>
    <message>
        <source>at %1 rad/s</source>
        <translation>em %1 rad/s</translation>
    </message>
    <message>
        <source>✓ both axes meet it</source>
        <translation>✓ os dois eixos a atendem</translation>
    </message>
    <message>
        <source>✗ fails: hover for why</source>
        <translation>✗ falha: passe o mouse para ver por quê</translation>
    </message>
    <message>
        <source>Set the limits to what this design reaches: %1 (one undo step)</source>
        <translation>Ajustar os limites ao que este projeto alcança: %1 (um passo de desfazer)</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>The design meets the specification</source>
        <translation>O projeto atende à especificação</translation>
    </message>
    <message>
        <source>No limit makes this design pass (see why): change the design</source>
        <translation>Nenhum limite faz este projeto passar (veja por quê): mude o projeto</translation>
    </message>
    <message>
        <source>Contour error (XY): max %1, RMS %2 mm</source>
        <translation>Erro de contorno (XY): máx %1, RMS %2 mm</translation>
    </message>
    <message>
        <source>The program&apos;s warnings are shown on the XY contour view</source>
        <translation>Os avisos do programa são mostrados na vista Contorno XY</translation>
    </message>
    <message>
        <source>CW</source>
        <translation>H</translation>
    </message>
    <message>
        <source>CCW</source>
        <translation>AH</translation>
    </message>
    <message>
        <source>ISO 230-4: G %1 %2, %3 %4, F %5/%6</source>
        <translation>ISO 230-4: G %1 %2, %3 %4, F %5/%6</translation>
    </message>
    <message>
        <source>ISO 230-4: G %1, F %2/%3</source>
        <translation>ISO 230-4: G %1, F %2/%3</translation>
    </message>
    <message>
        <source>, H %1</source>
        <translation>, H %1</translation>
    </message>
    <message>
        <source>%1° %2</source>
        <translation>%1° %2</translation>
    </message>
    <message>
        <source>, spikes ≤ %1</source>
        <translation>, picos ≤ %1</translation>
    </message>
    <message>
        <source>Reversal spikes (mm): %1</source>
        <translation>Picos de reversão (mm): %1</translation>
    </message>
    <message>
        <source>
Without the friction compensation: G %1 mm</source>
        <translation>
Sem a compensação de atrito: G %1 mm</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>program: %1</source>
        <translation>programa: %1</translation>
    </message>
    <message>
        <source>≤ %1</source>
        <translation>≤ %1</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
    </message>
    <message>
        <source>|e| ≤ %1</source>
        <translation>|e| ≤ %1</translation>
    </message>
    <message>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <source>%1: no design (%2: %3)</source>
        <translation>%1: sem projeto (%2: %3)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>&gt; %1</source>
        <translation>&gt; %1</translation>
    </message>
    <message>
        <source>%1*</source>
        <translation>%1*</translation>
    </message>
    <message>
        <source>unstable</source>
        <translation>instável</translation>
    </message>
    <message>
        <source>meets the specification, as designed and as implemented</source>
        <translation>atende à especificação, como projetado e como implementado</translation>
    </message>
    <message>
        <source>meets the specification</source>
        <translation>atende à especificação</translation>
    </message>
    <message>
        <source>fails the specification</source>
        <translation>não atende à especificação</translation>
    </message>
    <message>
        <source> digital</source>
        <translation> digital</translation>
    </message>
    <message>
        <source>the design meets the specification here, its digital implementation (Ts, quantization, ±umax, delay) does not: this is the implementation&apos;s figure</source>
        <translation>o projeto atende à especificação aqui, sua implementação digital (Ts, quantização, ±umax, atraso) não: este é o valor da implementação</translation>
    </message>
    <message>
        <source>not settled into ±%1 mm by the end of the run, %2 s after tf; %3</source>
        <translation>não acomodado em ±%1 mm até o fim da simulação, %2 s após tf; %3</translation>
    </message>
    <message>
        <source>design %1, digital %2%3</source>
        <translation>projeto %1, digital %2%3</translation>
    </message>
    <message>
        <source> (differs by more than 5 %)</source>
        <translation> (difere em mais de 5 %)</translation>
    </message>
    <message>
        <source>digital loop %1, design %2 at Ts = %3 s</source>
        <translation>malha digital %1, projeto %2 com Ts = %3 s</translation>
    </message>
    <message>
        <source>* not applied: the discrete loop of Patrick, Ishak and Adnan is simulated without a limit; |u| would be clipped this long</source>
        <translation>* não aplicado: a malha discreta de Patrick, Ishak e Adnan é simulada sem limite; |u| seria limitado por este tempo</translation>
    </message>
    <message>
        <source>RMSE (mm): the root mean square of the tracking error e = r − y over the samples of the run on the trajectory.</source>
        <translation>RMSE (mm): a raiz do valor quadrático médio do erro de seguimento e = r − y sobre as amostras da simulação na trajetória.</translation>
    </message>
    <message>
        <source>max |e| (mm): the largest absolute tracking error e = r − y over the run on the trajectory.</source>
        <translation>|e| máx (mm): o maior erro de seguimento absoluto e = r − y ao longo da simulação na trajetória.</translation>
    </message>
    <message>
        <source>max |e| (%): the largest absolute tracking error as a percentage of the travel; judged against the specification&apos;s maximum error.</source>
        <translation>|e| máx (%): o maior erro de seguimento absoluto como porcentagem do curso; avaliado frente ao erro máximo da especificação.</translation>
    </message>
    <message>
        <source>max |u| (V): the largest absolute command applied to the plant over the run (after the ±umax limit).</source>
        <translation>|u| máx (V): o maior comando absoluto aplicado à planta ao longo da simulação (após o limite de ±umax).</translation>
    </message>
    <message>
        <source>saturated (s): the time the command spends clipped at ±umax during the run (sample count × dt).</source>
        <translation>saturado (s): o tempo que o comando passa limitado em ±umax durante a simulação (número de amostras × dt).</translation>
    </message>
    <message>
        <source>ITAE (mm·s²): the integral of t·|e(t)| over the run (trapezoidal rule on the samples); it weighs late errors more than early ones.</source>
        <translation>ITAE (mm·s²): a integral de t·|e(t)| ao longo da simulação (regra dos trapézios sobre as amostras); pondera mais os erros tardios que os iniciais.</translation>
    </message>
    <message>
        <source>ZPETC gain (%): the RMSE improvement of the ZPETC feedforward over the loop alone, 100 (1 − RMSE with / RMSE without).</source>
        <translation>ganho do ZPETC (%): a melhora do RMSE com a pré-alimentação ZPETC em relação à malha sozinha, 100 (1 − RMSE com / RMSE sem).</translation>
    </message>
    <message>
        <source>settle time (s): from the end of the move (tf) until |e| stays inside the in-position window; judged against the specification&apos;s settle limit.</source>
        <translation>tempo de acomodação (s): do fim do movimento (tf) até |e| permanecer dentro da janela de posição; avaliado frente ao limite de acomodação da especificação.</translation>
    </message>
    <message>
        <source>final e (mm): the tracking error r − y at the last sample of the run.</source>
        <translation>e final (mm): o erro de seguimento r − y na última amostra da simulação.</translation>
    </message>
    <message>
        <source>overrun (mm): how far the axis went beyond the target after tf, in the direction of travel (0 when it never passed it).</source>
        <translation>ultrapassagem (mm): quanto o eixo foi além do alvo após tf, no sentido do movimento (0 quando nunca o ultrapassou).</translation>
    </message>
    <message>
        <source>settling 2 % (s): the time after which the closed loop&apos;s unit step stays within ±2 % of its final value.</source>
        <translation>acomodação 2 % (s): o tempo após o qual o degrau unitário da malha fechada permanece dentro de ±2 % do seu valor final.</translation>
    </message>
    <message>
        <source>overshoot (%): the unit step&apos;s peak above its final value, 100 (peak − final)/final; judged against the specification&apos;s maximum overshoot.</source>
        <translation>sobressinal (%): o pico do degrau unitário acima do seu valor final, 100 (pico − final)/final; avaliado frente ao sobressinal máximo da especificação.</translation>
    </message>
    <message>
        <source>RMSE (mm) of the digital implementation: the same figure for the sampled-data loop (controller at its Ts, hold, quantization, limit, delay); amber when it differs from the design&apos;s by more than 5 %.</source>
        <translation>RMSE (mm) da implementação digital: o mesmo valor para a malha amostrada (controlador no seu Ts, retentor, quantização, limite, atraso); em âmbar quando difere do valor do projeto em mais de 5 %.</translation>
    </message>
    <message>
        <source>max |e| (mm) of the digital implementation: the largest absolute error of the sampled-data loop&apos;s run; amber when it differs from the design&apos;s by more than 5 %.</source>
        <translation>|e| máx (mm) da implementação digital: o maior erro absoluto da simulação da malha amostrada; em âmbar quando difere do valor do projeto em mais de 5 %.</translation>
    </message>
    <message>
        <source>min ζ: the least damping ratio of the digital closed loop&apos;s poles, ζ = −Re s/|s| with s = ln z / Ts; the design&apos;s in the tooltip.</source>
        <translation>ζ mín: o menor coeficiente de amortecimento dos polos da malha fechada digital, ζ = −Re s/|s| com s = ln z / Ts; o do projeto aparece na dica.</translation>
    </message>
    <message>
        <source>Gain margin (dB): −20 log10 |L(jω180)| at the phase crossover ω180 where arg L = −180°: how much the loop gain may grow before the closed loop becomes unstable; ∞: never. Computed on the continuous loop.</source>
        <translation>Margem de ganho (dB): −20 log10 |L(jω180)| na frequência de cruzamento de fase ω180, onde arg L = −180°: quanto o ganho de malha pode crescer antes que a malha fechada se torne instável; ∞: nunca. Calculada na malha contínua.</translation>
    </message>
    <message>
        <source>Phase margin (°): 180° + arg L(jωc) at the gain crossover ωc where |L| = 1; computed on the continuous loop.</source>
        <translation>Margem de fase (°): 180° + arg L(jωc) na frequência de cruzamento de ganho ωc, onde |L| = 1; calculada na malha contínua.</translation>
    </message>
    <message>
        <source>Delay margin (s): the extra loop delay the closed loop tolerates, phase margin (rad) / ωc, the smallest over the gain crossovers.</source>
        <translation>Margem de atraso (s): o atraso adicional na malha que a malha fechada tolera, margem de fase (rad) / ωc, a menor entre os cruzamentos de ganho.</translation>
    </message>
    <message>
        <source>Ms: the peak of the sensitivity |S(jω)| = |1/(1 + L(jω))|, i.e. 1 / the closest distance of L to −1; 1.2–2 is a usual target.</source>
        <translation>Ms: o pico da sensibilidade |S(jω)| = |1/(1 + L(jω))|, isto é, 1 / a menor distância de L a −1; 1.2–2 é um alvo usual.</translation>
    </message>
    <message>
        <source>must be 0 .. 180 degrees</source>
        <translation>deve estar entre 0 e 180 graus</translation>
    </message>
    <message>
        <source>must be &gt;= 0 dB</source>
        <translation>deve ser &gt;= 0 dB</translation>
    </message>
</context>
<context>
    <name>xyt::ui::NumberField</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>xyt::ui::NyquistPlot</name>
    <message>
        <source>Nyquist diagram</source>
        <translation>Diagrama de Nyquist</translation>
    </message>
    <message>
        <source>Re L</source>
        <translation>Re L</translation>
    </message>
    <message>
        <source>Im L</source>
        <translation>Im L</translation>
    </message>
    <message>
        <source>|L| = 1</source>
        <translation>|L| = 1</translation>
    </message>
    <message>
        <source>distance 1/Ms to −1</source>
        <translation>distância 1/Ms até −1</translation>
    </message>
    <message>
        <source>L(jω), ω ≥ 0</source>
        <translation>L(jω), ω ≥ 0</translation>
    </message>
    <message>
        <source>ω &lt; 0 (mirror)</source>
        <translation>ω &lt; 0 (espelho)</translation>
    </message>
    <message>
        <source>−1</source>
        <translation>−1</translation>
    </message>
    <message>
        <source>the curve passes through −1: a closed-loop pole on the stability boundary</source>
        <translation>a curva passa por −1: um polo de malha fechada no limite de estabilidade</translation>
    </message>
    <message>
        <source>closed loop stable</source>
        <translation>malha fechada estável</translation>
    </message>
    <message>
        <source>%1 closed-loop pole(s) unstable</source>
        <translation>%1 polo(s) de malha fechada instável(is)</translation>
    </message>
    <message>
        <source>Nyquist: N = %1 clockwise encirclements of −1, P = %2 unstable open-loop poles → Z = N + P = %3: %4   (Ms = %5)</source>
        <translation>Nyquist: N = %1 envolvimentos de −1 no sentido horário, P = %2 polos de malha aberta instáveis → Z = N + P = %3: %4   (Ms = %5)</translation>
    </message>
    <message>
        <source>∞</source>
        <translation>∞</translation>
    </message>
    <message>
        <source>n/a, the closed loop is unstable</source>
        <translation>n/d, a malha fechada é instável</translation>
    </message>
    <message>
        <source>poles on the boundary are passed on small indentations: the curve closes at infinity there</source>
        <translation>polos no limite são contornados por pequenas indentações: a curva se fecha no infinito ali</translation>
    </message>
    <message>
        <source>Nyquist diagram: L(jω) in the complex plane for ω from 0 to ∞ (mirrored for negative ω), with the critical point −1; Z = N + P counts the closed-loop unstable poles from the encirclements N of −1 and the open-loop unstable poles P.</source>
        <translation>Diagrama de Nyquist: L(jω) no plano complexo para ω de 0 a ∞ (espelhado para ω negativo), com o ponto crítico −1; Z = N + P conta os polos instáveis de malha fechada a partir dos envolvimentos N de −1 e dos polos instáveis de malha aberta P.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::NyquistView</name>
    <message>
        <source>Nyquist diagram of %1</source>
        <translation>Diagrama de Nyquist de %1</translation>
    </message>
    <message>
        <source>No frequency analysis: %1</source>
        <translation>Sem análise em frequência: %1</translation>
    </message>
    <message>
        <source>Nyquist diagram of %1 (open loop L)</source>
        <translation>Diagrama de Nyquist de %1 (malha aberta L)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ParameterLocusPlot</name>
    <message>
        <source>real</source>
        <translation>real</translation>
    </message>
    <message>
        <source>imaginary</source>
        <translation>imaginário</translation>
    </message>
    <message>
        <source>current design</source>
        <translation>projeto atual</translation>
    </message>
    <message>
        <source>start of the sweep</source>
        <translation>início da varredura</translation>
    </message>
    <message>
        <source>stability boundary crossed</source>
        <translation>limite de estabilidade cruzado</translation>
    </message>
    <message>
        <source>framed on the poles that move; one pole barely moves and may lie outside the view: %1</source>
        <translation>enquadrado nos polos que se movem; um polo quase não se move e pode ficar fora da vista: %1</translation>
    </message>
    <message>
        <source>framed on the poles that move; %1 poles barely move and may lie outside the view: %2</source>
        <translation>enquadrado nos polos que se movem; %1 polos quase não se movem e podem ficar fora da vista: %2</translation>
    </message>
    <message>
        <source>unstable above %1 = %2</source>
        <translation>instável acima de %1 = %2</translation>
    </message>
    <message>
        <source>unstable below %1 = %2</source>
        <translation>instável abaixo de %1 = %2</translation>
    </message>
    <message>
        <source>Parameter locus: the closed-loop poles as the chosen parameter (ωn or kp) sweeps its range, with the design&apos;s value marked and the value where the loop turns unstable (a pole crossing the imaginary axis) marked.</source>
        <translation>Lugar do parâmetro: os polos de malha fechada à medida que o parâmetro escolhido (ωn ou kp) varre sua faixa, com o valor do projeto marcado e também o valor em que a malha se torna instável (um polo cruzando o eixo imaginário).</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ParameterLocusView</name>
    <message>
        <source>Parameter locus of %1</source>
        <translation>Lugar do parâmetro de %1</translation>
    </message>
    <message>
        <source>The parameter locus sweeps ωn or kp of a Guillemin–Truxal axis. This axis uses pole placement: its closed-loop poles are the roots of T = 1 + t1 z⁻¹ (pole at z = %1), placed directly by t1.</source>
        <translation>O lugar do parâmetro varre ωn ou kp de um eixo Guillemin–Truxal. Este eixo usa alocação de polos: seus polos de malha fechada são as raízes de T = 1 + t1 z⁻¹ (polo em z = %1), alocados diretamente por t1.</translation>
    </message>
    <message>
        <source>The parameter locus sweeps ωn or kp of a Guillemin–Truxal axis. This axis uses %1: the root locus shows its poles against the loop gain.</source>
        <translation>O lugar do parâmetro varre ωn ou kp de um eixo Guillemin–Truxal. Este eixo usa %1: o lugar das raízes mostra seus polos em função do ganho de malha.</translation>
    </message>
    <message>
        <source>Closed-loop poles as kp sweeps %1 … %2 (ωn = %3)</source>
        <translation>Polos de malha fechada com kp varrendo %1 … %2 (ωn = %3)</translation>
    </message>
    <message>
        <source>Closed-loop poles as ωn sweeps %1 … %2 rad/s (kp = %3)</source>
        <translation>Polos de malha fechada com ωn varrendo %1 … %2 rad/s (kp = %3)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ParameterSlider</name>
    <message>
        <source>%1 (logarithmic scale)</source>
        <translation>%1 (escala logarítmica)</translation>
    </message>
    <message>
        <source> value</source>
        <translation> valor</translation>
    </message>
    <message>
        <source>%1, beyond the slider (%2 to %3)</source>
        <translation>%1, além do controle deslizante (%2 a %3)</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number from %3 to %4</source>
        <translation>%1: &apos;%2&apos; não é um número de %3 a %4</translation>
    </message>
    <message>
        <source>%1
Type a value (scientific notation such as 2.5e3 is accepted).</source>
        <translation>%1
Digite um valor (notação científica como 2.5e3 é aceita).</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PidFeedforwardEditor</name>
    <message>
        <source>From model</source>
        <translation>Do modelo</translation>
    </message>
    <message>
        <source>D on the measurement (no kick)</source>
        <translation>D na medição (sem pico)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Feedforward&lt;/b&gt;, % of the model&apos;s inverse</source>
        <translation>&lt;b&gt;Pré-alimentação&lt;/b&gt;, % da inversa do modelo</translation>
    </message>
    <message>
        <source>FF1 (velocity)</source>
        <translation>FF1 (velocidade)</translation>
    </message>
    <message>
        <source>FF2 (acceleration)</source>
        <translation>FF2 (aceleração)</translation>
    </message>
    <message>
        <source>FF3 (jerk)</source>
        <translation>FF3 (jerk)</translation>
    </message>
    <message>
        <source>Set %1 of %2 to %3 % of the model</source>
        <translation>Definir %1 de %2 como %3 % do modelo</translation>
    </message>
    <message>
        <source>Set FF1, FF2 and FF3 to the plant&apos;s exact inverse (a2 u/k0, a1 u/k0, u/k0) and FF0 to 0</source>
        <translation>Definir FF1, FF2 e FF3 como a inversa exata da planta (a2 u/k0, a1 u/k0, u/k0) e FF0 como 0</translation>
    </message>
    <message>
        <source>Feedforward of %1 from the model</source>
        <translation>Pré-alimentação de %1 a partir do modelo</translation>
    </message>
    <message>
        <source>r′, r″, r‴ by backward differences</source>
        <translation>r′, r″, r‴ por diferenças regressivas</translation>
    </message>
    <message>
        <source>r′, r″, r‴ from the trajectory</source>
        <translation>r′, r″, r‴ da trajetória</translation>
    </message>
    <message>
        <source>Where the feedforward reads the command&apos;s derivatives: backward differences of the commanded position each period (LinuxCNC&apos;s pid), or the trajectory generator&apos;s own velocity, acceleration and jerk</source>
        <translation>De onde a pré-alimentação lê as derivadas do comando: diferenças regressivas da posição comandada a cada período (o pid do LinuxCNC), ou a velocidade, aceleração e jerk do próprio gerador de trajetória</translation>
    </message>
    <message>
        <source>Command derivatives</source>
        <translation>Derivadas do comando</translation>
    </message>
    <message>
        <source>Take the command&apos;s derivatives of %1 from the %2</source>
        <translation>Obter as derivadas do comando de %1 por %2</translation>
    </message>
    <message>
        <source>backward differences</source>
        <translation>diferenças regressivas</translation>
    </message>
    <message>
        <source>trajectory generator</source>
        <translation>gerador de trajetória</translation>
    </message>
    <message>
        <source>&lt;b&gt;Limits and filter&lt;/b&gt;</source>
        <translation>&lt;b&gt;Limites e filtro&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Differentiate the measurement of %1</source>
        <translation>Derivar a medição de %1</translation>
    </message>
    <message>
        <source>Differentiate the error of %1</source>
        <translation>Derivar o erro de %1</translation>
    </message>
    <message>
        <source>The plant has no usable inverse (k0 must be finite and nonzero): no feedforward from the model.</source>
        <translation>A planta não tem inversa utilizável (k0 deve ser finito e não nulo): sem pré-alimentação a partir do modelo.</translation>
    </message>
    <message>
        <source>100 % = FF1 %1 V/(mm/s), FF2 %2 V/(mm/s²), FF3 %3 V/(mm/s³)</source>
        <translation>100 % = FF1 %1 V/(mm/s), FF2 %2 V/(mm/s²), FF3 %3 V/(mm/s³)</translation>
    </message>
    <message>
        <source>The gain %1 as a percentage (%) of the plant&apos;s exact inverse (FF1 = a2 u/k0, FF2 = a1 u/k0, FF3 = u/k0): 100 % cancels the plant&apos;s dynamics along the trajectory</source>
        <translation>O ganho %1 como porcentagem (%) da inversa exata da planta (FF1 = a2 u/k0, FF2 = a1 u/k0, FF3 = u/k0): 100 % cancela a dinâmica da planta ao longo da trajetória</translation>
    </message>
    <message>
        <source>The D term differentiates the measured position (D = −fb′) instead of the error, so a step of the command gives no kick</source>
        <translation>O termo D deriva a posição medida (D = −fb′) em vez do erro, de modo que um degrau no comando não provoca pico (derivative kick)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PidTuningDialog</name>
    <message>
        <source>Tune the PID of axis %1</source>
        <translation>Sintonizar o PID do eixo %1</translation>
    </message>
    <message>
        <source>PI</source>
        <translation>PI</translation>
    </message>
    <message>
        <source>PID (Ti = 4 Td)</source>
        <translation>PID (Ti = 4 Td)</translation>
    </message>
    <message>
        <source>Controller structure</source>
        <translation>Estrutura do controlador</translation>
    </message>
    <message>
        <source>Structure</source>
        <translation>Estrutura</translation>
    </message>
    <message>
        <source>Crossover ωc (rad/s)</source>
        <translation>Cruzamento ωc (rad/s)</translation>
    </message>
    <message>
        <source>Phase margin (°)</source>
        <translation>Margem de fase (°)</translation>
    </message>
    <message>
        <source>Relay amplitude d (V)</source>
        <translation>Amplitude do relé d (V)</translation>
    </message>
    <message>
        <source>Rule</source>
        <translation>Regra</translation>
    </message>
    <message>
        <source>P (V/mm)</source>
        <translation>P (V/mm)</translation>
    </message>
    <message>
        <source>I (V/(mm s))</source>
        <translation>I (V/(mm s))</translation>
    </message>
    <message>
        <source>D (V s/mm)</source>
        <translation>D (V s/mm)</translation>
    </message>
    <message>
        <source>ωc (rad/s)</source>
        <translation>ωc (rad/s)</translation>
    </message>
    <message>
        <source>PM (°)</source>
        <translation>MF (°)</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <source>position y (mm)</source>
        <translation>posição y (mm)</translation>
    </message>
    <message>
        <source>relay u (V)</source>
        <translation>relé u (V)</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>u (V)</source>
        <translation>u (V)</translation>
    </message>
    <message>
        <source>Crossover and phase margin</source>
        <translation>Cruzamento e margem de fase</translation>
    </message>
    <message>
        <source>Relay: Ziegler–Nichols</source>
        <translation>Relé: Ziegler–Nichols</translation>
    </message>
    <message>
        <source>Relay: Tyreus–Luyben</source>
        <translation>Relé: Tyreus–Luyben</translation>
    </message>
    <message>
        <source>Relay limit cycle on the model: period Tu = %1 s, amplitude a = %2 mm, Ku = 4d/(πa) = %3 V/mm (describing function: Tu = %4 s, a = %5 mm).</source>
        <translation>Ciclo-limite do relé no modelo: período Tu = %1 s, amplitude a = %2 mm, Ku = 4d/(πa) = %3 V/mm (função descritiva: Tu = %4 s, a = %5 mm).</translation>
    </message>
    <message>
        <source>No relay experiment: %1</source>
        <translation>Sem ensaio de relé: %1</translation>
    </message>
    <message>
        <source>Tune %1 by %2</source>
        <translation>Sintonizar %1 por %2</translation>
    </message>
    <message>
        <source>PI, or PID with Ti = 4 Td, for the closed-form rule</source>
        <translation>PI, ou PID com Ti = 4 Td, para a regra em forma fechada</translation>
    </message>
    <message>
        <source>Target gain crossover ωc (rad/s): the closed-form gains make |L(jωc)| = 1, L = (P + I/s + D s) G/u</source>
        <translation>Frequência de cruzamento de ganho desejada ωc (rad/s): os ganhos em forma fechada fazem |L(jωc)| = 1, L = (P + I/s + D s) G/u</translation>
    </message>
    <message>
        <source>Target phase margin (°) at ωc: arg L(jωc) = −180° + PM</source>
        <translation>Margem de fase desejada (°) em ωc: arg L(jωc) = −180° + PM</translation>
    </message>
    <message>
        <source>Relay amplitude d (V) of the simulated relay experiment; its limit cycle&apos;s amplitude a and period Tu give Ku = 4d/(πa) for Ziegler–Nichols and Tyreus–Luyben</source>
        <translation>Amplitude d (V) do relé no ensaio de relé simulado; a amplitude a e o período Tu do seu ciclo-limite dão Ku = 4d/(πa) para Ziegler–Nichols e Tyreus–Luyben</translation>
    </message>
    <message>
        <source>Set this row&apos;s P, I and D on the axis (one undoable step)</source>
        <translation>Aplicar P, I e D desta linha ao eixo (um passo que pode ser desfeito)</translation>
    </message>
    <message>
        <source>The simulated relay experiment: the position y (mm) and the relay&apos;s command u (V) against time (s), settling into the limit cycle</source>
        <translation>O ensaio de relé simulado: a posição y (mm) e o comando u (V) do relé em função do tempo (s), acomodando-se no ciclo-limite</translation>
    </message>
    <message>
        <source>must be between 0 and 180 degrees</source>
        <translation>deve estar entre 0 e 180 graus</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PlantEditor</name>
    <message>
        <source>custom</source>
        <translation>personalizado</translation>
    </message>
    <message>
        <source>Plant preset</source>
        <translation>Predefinição da planta</translation>
    </message>
    <message>
        <source>Gain k0 of G(s) = k0 / (s³ + a1 s² + a2 s), in model units per volt·s³</source>
        <translation>Ganho k0 de G(s) = k0 / (s³ + a1 s² + a2 s), em unidades do modelo por volt·s³</translation>
    </message>
    <message>
        <source>Model output units per mm of trajectory (0.001: the model is in metres)</source>
        <translation>Unidades da saída do modelo por mm de trajetória (0.001: o modelo está em metros)</translation>
    </message>
    <message>
        <source>G(s) = k0 / (s³ + a1 s² + a2 s)</source>
        <translation>G(s) = k0 / (s³ + a1 s² + a2 s)</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>Predefinição</translation>
    </message>
    <message>
        <source>k&amp;0</source>
        <translation>k&amp;0</translation>
    </message>
    <message>
        <source>a&amp;1</source>
        <translation>a&amp;1</translation>
    </message>
    <message>
        <source>a&amp;2</source>
        <translation>a&amp;2</translation>
    </message>
    <message>
        <source>Model unit per mm</source>
        <translation>Unidade do modelo por mm</translation>
    </message>
    <message>
        <source>A plant of Braga et al.: the lower base (Eq. 2) or the upper base (Eq. 1) with the paper&apos;s ωn and kp; &quot;custom&quot; once a coefficient is edited</source>
        <translation>Uma planta de Braga et al.: a base inferior (Eq. 2) ou a base superior (Eq. 1) com os ωn e kp do artigo; &quot;personalizada&quot; assim que um coeficiente é editado</translation>
    </message>
    <message>
        <source>Coefficient a1 (1/s) of G(s) = k0 / (s³ + a1 s² + a2 s): the sum of the two non-zero poles&apos; magnitudes</source>
        <translation>Coeficiente a1 (1/s) de G(s) = k0 / (s³ + a1 s² + a2 s): a soma dos módulos dos dois polos não nulos</translation>
    </message>
    <message>
        <source>Coefficient a2 (1/s²) of G(s) = k0 / (s³ + a1 s² + a2 s): the product of the two non-zero poles; k0/a2 is the velocity gain</source>
        <translation>Coeficiente a2 (1/s²) de G(s) = k0 / (s³ + a1 s² + a2 s): o produto dos dois polos não nulos; k0/a2 é o ganho de velocidade</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PoleZeroPlot</name>
    <message>
        <source>Pole-zero map</source>
        <translation>Mapa de polos e zeros</translation>
    </message>
    <message>
        <source>real</source>
        <translation>real</translation>
    </message>
    <message>
        <source>imaginary</source>
        <translation>imaginário</translation>
    </message>
    <message>
        <source>Pole-zero map: the plant&apos;s, controller&apos;s and closed loop&apos;s poles (×) and zeros (○) in the s-plane, or in the z-plane for the digital loop (View › Pole-zero map of the digital loop), with lines of constant damping.</source>
        <translation>Mapa de polos e zeros: os polos (×) e zeros (○) da planta, do controlador e da malha fechada no plano s, ou no plano z para a malha digital (Exibir › Mapa de polos e zeros da malha digital), com linhas de amortecimento constante.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PoleZeroView</name>
    <message>
        <source>Pole-zero map of %1</source>
        <translation>Mapa de polos e zeros de %1</translation>
    </message>
    <message>
        <source>Digital loop of %1 in the z-plane (Ts = %2 s)</source>
        <translation>Malha digital de %1 no plano z (Ts = %2 s)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PpEditor</name>
    <message>
        <source>B(z⁻¹)/A(z⁻¹), ascending powers of z⁻¹</source>
        <translation>B(z⁻¹)/A(z⁻¹), potências crescentes de z⁻¹</translation>
    </message>
    <message>
        <source>custom</source>
        <translation>personalizado</translation>
    </message>
    <message>
        <source>ARX preset</source>
        <translation>Predefinição ARX</translation>
    </message>
    <message>
        <source>A(z⁻¹) = 1 + a1 z⁻¹ + ...: coefficients separated by spaces or commas</source>
        <translation>A(z⁻¹) = 1 + a1 z⁻¹ + ...: coeficientes separados por espaços ou vírgulas</translation>
    </message>
    <message>
        <source>B(z⁻¹) = 0 + b1 z⁻¹ + ...: leading zeros are the delay</source>
        <translation>B(z⁻¹) = 0 + b1 z⁻¹ + ...: os zeros iniciais são o atraso</translation>
    </message>
    <message>
        <source>Desired pole t&amp;1 (T = 1 + t1 z⁻¹)</source>
        <translation>Polo desejado t&amp;1 (T = 1 + t1 z⁻¹)</translation>
    </message>
    <message>
        <source>ZPETC feedforward</source>
        <translation>Pré-alimentação ZPETC</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>Predefinição</translation>
    </message>
    <message>
        <source>&amp;A</source>
        <translation>&amp;A</translation>
    </message>
    <message>
        <source>&amp;B</source>
        <translation>&amp;B</translation>
    </message>
    <message>
        <source>Ts (s)</source>
        <translation>Ts (s)</translation>
    </message>
    <message>
        <source>An axis model of Patrick, Ishak and Adnan: the x axis (Eq. 1) or the y axis (Eq. 3), with T = 1 − 0.2 z⁻¹ and Ts = 70 ms</source>
        <translation>Um modelo de eixo de Patrick, Ishak e Adnan: o eixo x (Eq. 1) ou o eixo y (Eq. 3), com T = 1 − 0.2 z⁻¹ e Ts = 70 ms</translation>
    </message>
    <message>
        <source>The desired closed-loop pole: T = 1 + t1 z⁻¹ puts the RST loop&apos;s pole at z = −t1; the Diophantine equation A F + B G = T gives F, G</source>
        <translation>O polo de malha fechada desejado: T = 1 + t1 z⁻¹ coloca o polo da malha RST em z = −t1; a equação diofantina A F + B G = T fornece F e G</translation>
    </message>
    <message>
        <source>Sample time Ts (s) of the ARX model and of its RST controller</source>
        <translation>Período de amostragem Ts (s) do modelo ARX e do seu controlador RST</translation>
    </message>
    <message>
        <source>Tomizuka&apos;s zero-phase-error tracking controller ahead of the loop: u_ff(k) = A_c B⁻*(z⁻¹) / (B⁺ [B⁻(1)]²) r(k + p), the reference previewed p samples</source>
        <translation>O controlador de seguimento com erro de fase nulo (ZPETC) de Tomizuka antes da malha: u_ff(k) = A_c B⁻*(z⁻¹) / (B⁺ [B⁻(1)]²) r(k + p), com a referência antecipada em p amostras</translation>
    </message>
    <message>
        <source>the z^0 coefficient must be nonzero (A is monic)</source>
        <translation>o coeficiente de z^0 deve ser diferente de zero (A é mônico)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::PresenterView</name>
    <message>
        <source>Axis %1 (%2)</source>
        <translation>Eixo %1 (%2)</translation>
    </message>
    <message>
        <source>No design: %1: %2</source>
        <translation>Sem projeto: %1: %2</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ReportExporter</name>
    <message>
        <source>Export &amp;report (PDF)...</source>
        <translation>Exportar relatório (&amp;PDF)...</translation>
    </message>
    <message>
        <source>A PDF of the design for a lab report or a design review: plants, controllers, figures against the specification, warnings and plots</source>
        <translation>Um PDF do projeto para um relatório de laboratório ou uma revisão de projeto: plantas, controladores, valores frente à especificação, avisos e gráficos</translation>
    </message>
    <message>
        <source>Export report</source>
        <translation>Exportar relatório</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Writing the report...</source>
        <translation>Gravando o relatório...</translation>
    </message>
    <message>
        <source>The report was not written; any existing file is unchanged.

%1</source>
        <translation>O relatório não foi gravado; um arquivo já existente permanece inalterado.

%1</translation>
    </message>
    <message>
        <source>Report written to %1 (%2 s)</source>
        <translation>Relatório gravado em %1 (%2 s)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::ReportFigures</name>
    <message>
        <source>Axis %1</source>
        <translation>Eixo %1</translation>
    </message>
    <message>
        <source>Axis %1 (%2)</source>
        <translation>Eixo %1 (%2)</translation>
    </message>
    <message>
        <source>No design: %1: %2</source>
        <translation>Sem projeto: %1: %2</translation>
    </message>
    <message>
        <source>Root locus of %1 (K = 1: the design)</source>
        <translation>Lugar das raízes de %1 (K = 1: o projeto)</translation>
    </message>
    <message>
        <source>Root locus of the loop 1 + K L = 0; the closed-loop poles of the design (K = 1) are marked, with the region the specification allows.</source>
        <translation>Lugar das raízes da malha 1 + K L = 0; os polos de malha fechada do projeto (K = 1) estão marcados, com a região que a especificação permite.</translation>
    </message>
    <message>
        <source>Bode diagram of %1</source>
        <translation>Diagrama de Bode de %1</translation>
    </message>
    <message>
        <source>Bode diagram of the open loop L with the gain and phase margins, and the closed loop.</source>
        <translation>Diagrama de Bode da malha aberta L com as margens de ganho e de fase, e da malha fechada.</translation>
    </message>
    <message>
        <source>No frequency analysis: %1</source>
        <translation>Sem análise em frequência: %1</translation>
    </message>
    <message>
        <source>Unit step of %1</source>
        <translation>Degrau unitário de %1</translation>
    </message>
    <message>
        <source>Unit step of the closed loop, with the specification&apos;s overshoot and settling limits.</source>
        <translation>Degrau unitário da malha fechada, com os limites de sobressinal e de acomodação da especificação.</translation>
    </message>
    <message>
        <source>No step response: %1</source>
        <translation>Sem resposta ao degrau: %1</translation>
    </message>
    <message>
        <source>Response to the trajectory: reference and output, tracking error, control voltage; the digital implementation overlaid.</source>
        <translation>Resposta à trajetória: referência e saída, erro de seguimento, tensão de controle; com a implementação digital sobreposta.</translation>
    </message>
    <message>
        <source>The XY contour: commanded and traced path, the error magnified about the path.</source>
        <translation>O contorno XY: percurso comandado e percurso traçado, com o erro ampliado em torno do percurso.</translation>
    </message>
    <message>
        <source>Ballbar view of the circle (ISO 230-4): the radial deviation magnified about the nominal centre.</source>
        <translation>Vista de ballbar do círculo (ISO 230-4): o desvio radial ampliado em torno do centro nominal.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::RobustnessView</name>
    <message>
        <source>The analysis failed: %1</source>
        <translation>A análise falhou: %1</translation>
    </message>
    <message>
        <source>Ranges (± %)</source>
        <translation>Faixas (± %)</translation>
    </message>
    <message>
        <source>random plants, drawn uniformly within the ranges</source>
        <translation>plantas aleatórias, sorteadas uniformemente dentro das faixas</translation>
    </message>
    <message>
        <source>the same seed draws the same plants</source>
        <translation>a mesma semente sorteia as mesmas plantas</translation>
    </message>
    <message>
        <source>corners</source>
        <translation>vértices</translation>
    </message>
    <message>
        <source>also every corner of the box of ranges (the deterministic worst-case search)</source>
        <translation>também todos os vértices da caixa de faixas (a busca determinística do pior caso)</translation>
    </message>
    <message>
        <source>XY contour</source>
        <translation>Contorno XY</translation>
    </message>
    <message>
        <source>Analyze both axes together on the circle or G-code program: pairs of plants, the contour error they trace, its XY band. Each range applies to the parameter of that name on every axis that has one.</source>
        <translation>Analisar os dois eixos juntos no círculo ou no programa G-code: pares de plantas, o erro de contorno que percorrem, sua faixa XY. Cada faixa se aplica ao parâmetro com esse nome em todo eixo que o tenha.</translation>
    </message>
    <message>
        <source>the signal whose envelope is drawn</source>
        <translation>o sinal cuja envoltória é desenhada</translation>
    </message>
    <message>
        <source>the figure whose distribution is drawn</source>
        <translation>o valor cuja distribuição é desenhada</translation>
    </message>
    <message>
        <source>plants</source>
        <translation>plantas</translation>
    </message>
    <message>
        <source>seed</source>
        <translation>semente</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Executar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Load worst case</source>
        <translation>Carregar o pior caso</translation>
    </message>
    <message>
        <source>Make the worst plant found (largest RMSE) the session&apos;s plant (an undoable step)</source>
        <translation>Tornar a pior planta encontrada (maior RMSE) a planta da sessão (um passo que pode ser desfeito)</translation>
    </message>
    <message>
        <source>Set a range for the parameters you doubt and press Run.</source>
        <translation>Defina uma faixa para os parâmetros de que você duvida e clique em Executar.</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Mostrar</translation>
    </message>
    <message>
        <source>contour error</source>
        <translation>erro de contorno</translation>
    </message>
    <message>
        <source>max |contour e|</source>
        <translation>máx |e de contorno|</translation>
    </message>
    <message>
        <source>XY band</source>
        <translation>faixa XY</translation>
    </message>
    <message>
        <source>error e</source>
        <translation>erro e</translation>
    </message>
    <message>
        <source>output y</source>
        <translation>saída y</translation>
    </message>
    <message>
        <source>command u</source>
        <translation>comando u</translation>
    </message>
    <message>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <source>max |e|</source>
        <translation>máx |e|</translation>
    </message>
    <message>
        <source>max |u|</source>
        <translation>máx |u|</translation>
    </message>
    <message>
        <source>ZPETC sensitivity</source>
        <translation>sensibilidade do ZPETC</translation>
    </message>
    <message>
        <source>XY contour: set the ranges and press Run.</source>
        <translation>Contorno XY: defina as faixas e clique em Executar.</translation>
    </message>
    <message>
        <source>Envelope</source>
        <translation>Envoltória</translation>
    </message>
    <message>
        <source>Distribution</source>
        <translation>Distribuição</translation>
    </message>
    <message>
        <source>%1 of every axis that has one: drawn uniformly within ± this share of its nominal</source>
        <translation>%1 de todo eixo que o tenha: sorteado uniformemente dentro de ± esta fração do nominal</translation>
    </message>
    <message>
        <source>%1: nominal %2; drawn uniformly within ± this share of it</source>
        <translation>%1: nominal %2; sorteado uniformemente dentro de ± esta fração dele</translation>
    </message>
    <message>
        <source>Not the current design&apos;s (computed for %1): %2</source>
        <translation>Não é do projeto atual (calculado para %1): %2</translation>
    </message>
    <message>
        <source>Computed for %1: this tab shows axis %2. Press Run to analyze it.</source>
        <translation>Calculado para %1: esta aba mostra o eixo %2. Clique em Executar para analisá-lo.</translation>
    </message>
    <message>
        <source>Computed for %1. The design has changed since: press Run to analyze the current one.</source>
        <translation>Calculado para %1. O projeto mudou desde então: clique em Executar para analisar o atual.</translation>
    </message>
    <message>
        <source>Cannot run: %1</source>
        <translation>Não é possível executar: %1</translation>
    </message>
    <message>
        <source>Running %1 plant pairs%2…</source>
        <translation>Simulando %1 pares de plantas%2…</translation>
    </message>
    <message>
        <source>Running %1 plants%2…</source>
        <translation>Simulando %1 plantas%2…</translation>
    </message>
    <message>
        <source> and the corners</source>
        <translation> e os vértices</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Cancelando…</translation>
    </message>
    <message>
        <source>Cancelled after %1 of %2 %3. </source>
        <translation>Cancelado após %1 de %2 %3. </translation>
    </message>
    <message>
        <source>%1 %2%3: </source>
        <translation>%1 %2%3: </translation>
    </message>
    <message>
        <source> + %1 corners</source>
        <translation> + %1 vértices</translation>
    </message>
    <message>
        <source>%1 % meet the spec (the nominal %2); %3 unstable.</source>
        <translation>%1 % atendem à especificação (o nominal %2); %3 instáveis.</translation>
    </message>
    <message>
        <source>does</source>
        <translation>atende</translation>
    </message>
    <message>
        <source>does not</source>
        <translation>não atende</translation>
    </message>
    <message>
        <source> The feedforward divides the RMSE by %1 on the median plant (%2 at the 95 % RMSE).</source>
        <translation> A pré-alimentação divide o RMSE por %1 na planta mediana (%2 no RMSE de 95 %).</translation>
    </message>
    <message>
        <source>
Worst: RMSE %1 mm at %2.</source>
        <translation>
Pior: RMSE %1 mm em %2.</translation>
    </message>
    <message>
        <source>
Unstable, e.g. at %1.</source>
        <translation>
Instável, p. ex. em %1.</translation>
    </message>
    <message>
        <source>plant pairs</source>
        <translation>pares de plantas</translation>
    </message>
    <message>
        <source>max contour error median %1 mm, 95 % %2 mm (nominal %3 mm); %4 unstable.</source>
        <translation>erro de contorno máx: mediana %1 mm, 95 % %2 mm (nominal %3 mm); %4 instáveis.</translation>
    </message>
    <message>
        <source>no stable pair; %1 unstable.</source>
        <translation>nenhum par estável; %1 instáveis.</translation>
    </message>
    <message>
        <source>
Worst: %1 mm at %2.</source>
        <translation>
Pior: %1 mm em %2.</translation>
    </message>
    <message>
        <source>Contour error of the plant pairs</source>
        <translation>Erro de contorno dos pares de plantas</translation>
    </message>
    <message>
        <source>contour e (mm)</source>
        <translation>e de contorno (mm)</translation>
    </message>
    <message>
        <source>max |contour e| (mm)</source>
        <translation>máx |e de contorno| (mm)</translation>
    </message>
    <message>
        <source>Error e of the plants</source>
        <translation>Erro e das plantas</translation>
    </message>
    <message>
        <source>Output y of the plants</source>
        <translation>Saída y das plantas</translation>
    </message>
    <message>
        <source>Command u of the plants</source>
        <translation>Comando u das plantas</translation>
    </message>
    <message>
        <source>e (mm)</source>
        <translation>e (mm)</translation>
    </message>
    <message>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <source>u (V)</source>
        <translation>u (V)</translation>
    </message>
    <message>
        <source>For a pole-placement axis with ZPETC.</source>
        <translation>Para um eixo por alocação de polos com ZPETC.</translation>
    </message>
    <message>
        <source>RMSE (mm)</source>
        <translation>RMSE (mm)</translation>
    </message>
    <message>
        <source>max |e| (mm)</source>
        <translation>máx |e| (mm)</translation>
    </message>
    <message>
        <source>max |u| (V)</source>
        <translation>máx |u| (V)</translation>
    </message>
    <message>
        <source>Load the worst plant pair of the contour analysis</source>
        <translation>Carregar o pior par de plantas da análise de contorno</translation>
    </message>
    <message>
        <source>Load the worst plant of the robustness analysis</source>
        <translation>Carregar a pior planta da análise de robustez</translation>
    </message>
    <message>
        <source>Run the analysis: the session&apos;s unchanged controller on every plant drawn within the ranges (and the box&apos;s corners), each on the trajectory</source>
        <translation>Executar a análise: o controlador da sessão, inalterado, em cada planta sorteada dentro das faixas (e nos vértices da caixa), cada uma na trajetória</translation>
    </message>
    <message>
        <source>Stop the analysis; the plants run so far are shown</source>
        <translation>Interromper a análise; as plantas simuladas até aqui são mostradas</translation>
    </message>
</context>
<context>
    <name>xyt::ui::RootLocusPlot</name>
    <message>
        <source>Root locus</source>
        <translation>Lugar das raízes</translation>
    </message>
    <message>
        <source>real</source>
        <translation>real</translation>
    </message>
    <message>
        <source>imaginary</source>
        <translation>imaginário</translation>
    </message>
    <message>
        <source>open-loop poles</source>
        <translation>polos de malha aberta</translation>
    </message>
    <message>
        <source>open-loop zeros</source>
        <translation>zeros de malha aberta</translation>
    </message>
    <message>
        <source>closed-loop poles</source>
        <translation>polos de malha fechada</translation>
    </message>
    <message>
        <source>hover a branch: K, ζ, ωn; click: use that gain</source>
        <translation>passe o mouse sobre um ramo: K, ζ, ωn; clique: usar esse ganho</translation>
    </message>
    <message>
        <source>open-loop zeros (drag to move)</source>
        <translation>zeros de malha aberta (arraste para mover)</translation>
    </message>
    <message>
        <source>the locus is incomplete</source>
        <translation>o lugar está incompleto</translation>
    </message>
    <message>
        <source>K = %1   ζ = %2   ωn = %3 rad/s   s = %4 %5 %6j</source>
        <translation>K = %1   ζ = %2   ωn = %3 rad/s   s = %4 %5 %6j</translation>
    </message>
    <message>
        <source>Root locus: the closed-loop poles of 1 + K L(s) = 0 as the loop gain K goes from 0 to ∞ (K = 1 is the design), with the specification&apos;s ζ wedge and settling line; click a point to apply its gain, drag a closed-loop pole along the locus or a PID&apos;s zero.</source>
        <translation>Lugar das raízes: os polos de malha fechada de 1 + K L(s) = 0 à medida que o ganho de malha K vai de 0 a ∞ (K = 1 é o projeto), com a cunha de ζ e a linha de acomodação da especificação; clique num ponto para aplicar seu ganho, arraste um polo de malha fechada ao longo do lugar ou um zero do PID.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::RootLocusView</name>
    <message>
        <source>Root locus of %1</source>
        <translation>Lugar das raízes de %1</translation>
    </message>
    <message>
        <source>Root locus of %1 (K = 1: the design)</source>
        <translation>Lugar das raízes de %1 (K = 1: o projeto)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::SensitivityPlot</name>
    <message>
        <source>ZPETC sensitivity</source>
        <translation>sensibilidade do ZPETC</translation>
    </message>
    <message>
        <source>mismatch (% of ranges)</source>
        <translation>discrepância (% das faixas)</translation>
    </message>
    <message>
        <source>RMSE (mm)</source>
        <translation>RMSE (mm)</translation>
    </message>
    <message>
        <source>with ZPETC</source>
        <translation>com ZPETC</translation>
    </message>
    <message>
        <source>loop alone</source>
        <translation>só a malha</translation>
    </message>
    <message>
        <source>Not computed yet.</source>
        <translation>Ainda não calculado.</translation>
    </message>
    <message>
        <source>No stable plant at any mismatch.</source>
        <translation>Nenhuma planta estável em nenhuma discrepância.</translation>
    </message>
    <message>
        <source>ZPETC sensitivity: the RMSE (mm) of the run with and without the feedforward as the plant mismatch grows from the nominal model (0 %) to the ranges set (100 %), each point over the same seeded plants.</source>
        <translation>Sensibilidade do ZPETC: o RMSE (mm) da simulação com e sem a pré-alimentação à medida que a discrepância da planta cresce do modelo nominal (0 %) até as faixas definidas (100 %), cada ponto sobre as mesmas plantas sorteadas com a mesma semente.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::SessionFileController</name>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Novo</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Abrir...</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;recente</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Salvar</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Salvar c&amp;omo...</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>E&amp;xportar</translation>
    </message>
    <message>
        <source>Coefficients as &amp;JSON...</source>
        <translation>Coeficientes como &amp;JSON...</translation>
    </message>
    <message>
        <source>Firmware &amp;C header...</source>
        <translation>Cabeçalho &amp;C para firmware...</translation>
    </message>
    <message>
        <source>&amp;Octave/MATLAB script...</source>
        <translation>Script &amp;Octave/MATLAB...</translation>
    </message>
    <message>
        <source>Simulated signals as CS&amp;V...</source>
        <translation>Sinais simulados como CS&amp;V...</translation>
    </message>
    <message>
        <source>Not for a G-code trajectory: the script computes the reference in closed form, and a program&apos;s feed profile has none. Export the simulated signals as CSV instead.</source>
        <translation>Não para uma trajetória G-code: o script calcula a referência em forma fechada, e o perfil de avanço de um programa não tem uma. Exporte os sinais simulados como CSV.</translation>
    </message>
    <message>
        <source>A GNU Octave / MATLAB script with each axis&apos; plant, controller and closed loop, plotting the response to the trajectory</source>
        <translation>Um script GNU Octave / MATLAB com a planta, o controlador e a malha fechada de cada eixo, traçando a resposta à trajetória</translation>
    </message>
    <message>
        <source>XY Tune</source>
        <translation>XY Tune</translation>
    </message>
    <message>
        <source>The design has unsaved changes. Save them first?</source>
        <translation>O projeto tem alterações não salvas. Salvá-las primeiro?</translation>
    </message>
    <message>
        <source>New session with the paper&apos;s default design</source>
        <translation>Nova sessão com o projeto padrão do artigo</translation>
    </message>
    <message>
        <source>Open session</source>
        <translation>Abrir sessão</translation>
    </message>
    <message>
        <source>XY Tune sessions (*.json);;All files (*)</source>
        <translation>Sessões do XY Tune (*.json);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>%1 could not be opened; the current design is unchanged.

%2</source>
        <translation>%1 não pôde ser aberto; o projeto atual não foi alterado.

%2</translation>
    </message>
    <message>
        <source>Opened with notes:
%1</source>
        <translation>Aberto com observações:
%1</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 aberto</translation>
    </message>
    <message>
        <source>Save session</source>
        <translation>Salvar sessão</translation>
    </message>
    <message>
        <source>XY Tune sessions (*.json)</source>
        <translation>Sessões do XY Tune (*.json)</translation>
    </message>
    <message>
        <source>The session was not saved; any existing file is unchanged.

%1</source>
        <translation>A sessão não foi salva; um arquivo existente não foi alterado.

%1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 salvo</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportado</translation>
    </message>
    <message>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <source>C header (*.h)</source>
        <translation>Cabeçalho C (*.h)</translation>
    </message>
    <message>
        <source>Octave/MATLAB script (*.m)</source>
        <translation>Script Octave/MATLAB (*.m)</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::SnapshotCompareDialog</name>
    <message>
        <source>Compare designs</source>
        <translation>Comparar projetos</translation>
    </message>
    <message>
        <source>Current design</source>
        <translation>Projeto atual</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Comparar</translation>
    </message>
    <message>
        <source>with</source>
        <translation>com</translation>
    </message>
    <message>
        <source>The first design of the comparison: the current one or a stored snapshot (Design › Store snapshot)</source>
        <translation>O primeiro projeto da comparação: o atual ou um instantâneo guardado (Projeto › Guardar instantâneo)</translation>
    </message>
    <message>
        <source>The second design of the comparison; the table lists both designs&apos; settings and figures side by side</source>
        <translation>O segundo projeto da comparação; a tabela lista as configurações e os valores dos dois projetos lado a lado</translation>
    </message>
</context>
<context>
    <name>xyt::ui::StepPlot</name>
    <message>
        <source>Step response</source>
        <translation>Resposta ao degrau</translation>
    </message>
    <message>
        <source>time after the step (s)</source>
        <translation>tempo após o degrau (s)</translation>
    </message>
    <message>
        <source>output (unit step)</source>
        <translation>saída (degrau unitário)</translation>
    </message>
    <message>
        <source>overshoot limit</source>
        <translation>limite de sobressinal</translation>
    </message>
    <message>
        <source>settling band</source>
        <translation>faixa de acomodação</translation>
    </message>
    <message>
        <source>violates the spec</source>
        <translation>viola a especificação</translation>
    </message>
    <message>
        <source>rise 10–90 %</source>
        <translation>subida 10–90 %</translation>
    </message>
    <message>
        <source>peak</source>
        <translation>pico</translation>
    </message>
    <message>
        <source>settling (2 %)</source>
        <translation>acomodação (2 %)</translation>
    </message>
    <message>
        <source>hover the plot: t and y of the step the axis runs</source>
        <translation>passe o mouse sobre o gráfico: t e y do degrau que o eixo executa</translation>
    </message>
    <message>
        <source>unstable: no step response (the closed loop has a pole outside the stability region)</source>
        <translation>instável: sem resposta ao degrau (a malha fechada tem um polo fora da região de estabilidade)</translation>
    </message>
    <message>
        <source>overshoot ≤ %1 %</source>
        <translation>sobressinal ≤ %1 %</translation>
    </message>
    <message>
        <source>overshoot limit %1 (%2 %) is above the view</source>
        <translation>o limite de sobressinal %1 (%2 %) está acima da vista</translation>
    </message>
    <message>
        <source>±%1 % after %2 s</source>
        <translation>±%1 % após %2 s</translation>
    </message>
    <message>
        <source>settling limit %1 s lies beyond the right edge (%2 s)</source>
        <translation>o limite de acomodação %1 s fica além da borda direita (%2 s)</translation>
    </message>
    <message>
        <source>  rise %1 s</source>
        <translation>  subida %1 s</translation>
    </message>
    <message>
        <source>the response never reaches 90 % of its final value in view</source>
        <translation>a resposta nunca atinge 90 % do valor final na vista</translation>
    </message>
    <message>
        <source>peak %1 at %2 s (%3 %)</source>
        <translation>pico %1 em %2 s (%3 %)</translation>
    </message>
    <message>
        <source>: beyond the right edge</source>
        <translation>: além da borda direita</translation>
    </message>
    <message>
        <source>settles %1 s</source>
        <translation>acomoda em %1 s</translation>
    </message>
    <message>
        <source>red: the response leaves the specification&apos;s envelope</source>
        <translation>vermelho: a resposta sai da envoltória da especificação</translation>
    </message>
    <message>
        <source>t = %1 s   y = %2   (%3)</source>
        <translation>t = %1 s   y = %2   (%3)</translation>
    </message>
    <message>
        <source>Unit step of the closed loop (not the trajectory): output against time (s), with the rise, peak and settling (2 % band) markers and the specification&apos;s overshoot and settling envelope; samples outside it are red.</source>
        <translation>Degrau unitário da malha fechada (não a trajetória): saída em função do tempo (s), com os marcadores de subida, pico e acomodação (faixa de 2 %) e a envoltória de sobressinal e acomodação da especificação; as amostras fora dela ficam em vermelho.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::StepResponseView</name>
    <message>
        <source>Unit step of %1</source>
        <translation>Degrau unitário de %1</translation>
    </message>
    <message>
        <source>No step response: %1</source>
        <translation>Sem resposta ao degrau: %1</translation>
    </message>
</context>
<context>
    <name>xyt::ui::TimeResponsePlot</name>
    <message>
        <source>position (mm)</source>
        <translation>posição (mm)</translation>
    </message>
    <message>
        <source>error (mm)</source>
        <translation>erro (mm)</translation>
    </message>
    <message>
        <source>u (V)</source>
        <translation>u (V)</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>reference r</source>
        <translation>referência r</translation>
    </message>
    <message>
        <source>snapshot</source>
        <translation>instantâneo</translation>
    </message>
    <message>
        <source>digital y</source>
        <translation>y digital</translation>
    </message>
    <message>
        <source>digital e</source>
        <translation>e digital</translation>
    </message>
    <message>
        <source>digital u (held)</source>
        <translation>u digital (retido)</translation>
    </message>
    <message>
        <source>y without the shaper</source>
        <translation>y sem o modelador</translation>
    </message>
    <message>
        <source>e without the shaper</source>
        <translation>e sem o modelador</translation>
    </message>
    <message>
        <source>output y</source>
        <translation>saída y</translation>
    </message>
    <message>
        <source>error e</source>
        <translation>erro e</translation>
    </message>
    <message>
        <source>table stuck</source>
        <translation>mesa presa</translation>
    </message>
    <message>
        <source>clipped</source>
        <translation>limitado</translation>
    </message>
    <message>
        <source>snapshot u</source>
        <translation>u do instantâneo</translation>
    </message>
    <message>
        <source>snapshot e</source>
        <translation>e do instantâneo</translation>
    </message>
    <message>
        <source>feedforward part</source>
        <translation>parte de pré-alimentação</translation>
    </message>
    <message>
        <source>feedback part</source>
        <translation>parte de realimentação</translation>
    </message>
    <message>
        <source>control u</source>
        <translation>controle u</translation>
    </message>
    <message>
        <source>linear loop: |u| is not clipped at ±%1 V here (the shaded time would saturate)</source>
        <translation>malha linear: |u| não é limitado em ±%1 V aqui (o tempo sombreado saturaria)</translation>
    </message>
    <message>
        <source>%1: not simulated (%2: %3)</source>
        <translation>%1: não simulado (%2: %3)</translation>
    </message>
    <message>
        <source>%1 — time response</source>
        <translation>%1 — resposta no tempo</translation>
    </message>
    <message>
        <source>  (UNSTABLE closed loop)</source>
        <translation>  (malha fechada INSTÁVEL)</translation>
    </message>
    <message>
        <source>digital y (Ts %1 s, held u)</source>
        <translation>y digital (Ts %1 s, u retido)</translation>
    </message>
    <message>
        <source>digital y (encoder, DAC, limit)</source>
        <translation>y digital (encoder, DAC, limite)</translation>
    </message>
    <message>
        <source>snapshot «%1» (y, e, u)</source>
        <translation>instantâneo «%1» (y, e, u)</translation>
    </message>
    <message>
        <source>Time response of the selected axis on the trajectory: reference r, output y and error e = r − y (mm), and the command u (V) with the ±umax band and clipped intervals shaded; the digital implementation&apos;s run as a translucent band.</source>
        <translation>Resposta no tempo do eixo selecionado na trajetória: referência r, saída y e erro e = r − y (mm), e o comando u (V) com a faixa de ±umax e os intervalos limitados sombreados; a simulação da implementação digital como uma faixa translúcida.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::TrajectoryEditor</name>
    <message>
        <source>Point-to-point (both axes)</source>
        <translation>Ponto a ponto (os dois eixos)</translation>
    </message>
    <message>
        <source>Circle (x = R sin ωt, y = R cos ωt)</source>
        <translation>Círculo (x = R sin ωt, y = R cos ωt)</translation>
    </message>
    <message>
        <source>G-code program (x and y along its feed profile)</source>
        <translation>Programa G-code (x e y ao longo do seu perfil de avanço)</translation>
    </message>
    <message>
        <source>Trajectory kind</source>
        <translation>Tipo de trajetória</translation>
    </message>
    <message>
        <source>cubic</source>
        <translation>cúbica</translation>
    </message>
    <message>
        <source>quintic</source>
        <translation>quíntica</translation>
    </message>
    <message>
        <source>Move profile</source>
        <translation>Perfil do movimento</translation>
    </message>
    <message>
        <source>The move&apos;s profile: Braga et al.&apos;s cubic, whose acceleration steps at the start and the end, or the quintic, whose acceleration starts and ends at zero, so a jerk feedforward sees no spike</source>
        <translation>O perfil do movimento: a cúbica de Braga et al., cuja aceleração salta no início e no fim, ou a quíntica, cuja aceleração começa e termina em zero, de modo que uma pré-alimentação de jerk não vê pico</translation>
    </message>
    <message>
        <source>x0 (mm)</source>
        <translation>x0 (mm)</translation>
    </message>
    <message>
        <source>xf (mm)</source>
        <translation>xf (mm)</translation>
    </message>
    <message>
        <source>t0 (s)</source>
        <translation>t0 (s)</translation>
    </message>
    <message>
        <source>tf (s)</source>
        <translation>tf (s)</translation>
    </message>
    <message>
        <source>v0 (mm/s)</source>
        <translation>v0 (mm/s)</translation>
    </message>
    <message>
        <source>vf (mm/s)</source>
        <translation>vf (mm/s)</translation>
    </message>
    <message>
        <source>Radius (mm)</source>
        <translation>Raio (mm)</translation>
    </message>
    <message>
        <source>ω (rad/s)</source>
        <translation>ω (rad/s)</translation>
    </message>
    <message>
        <source>Ramp-in (s)</source>
        <translation>Rampa de entrada (s)</translation>
    </message>
    <message>
        <source>0 = automatic: tf for a cubic, one revolution plus the ramp-in for a circle; a G-code program always runs its feed profile&apos;s time</source>
        <translation>0 = automático: tf para uma cúbica, uma volta mais a rampa de entrada para um círculo; um programa G-code sempre dura o tempo do seu perfil de avanço</translation>
    </message>
    <message>
        <source>Duration (s)</source>
        <translation>Duração (s)</translation>
    </message>
    <message>
        <source>Step dt (s)</source>
        <translation>Passo dt (s)</translation>
    </message>
    <message>
        <source>G-code program</source>
        <translation>Programa G-code</translation>
    </message>
    <message>
        <source>no program</source>
        <translation>nenhum programa</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Abrir…</translation>
    </message>
    <message>
        <source>Read a G-code program (.nc); it is kept in the session</source>
        <translation>Ler um programa G-code (.nc); ele é guardado na sessão</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <source>Example programs</source>
        <translation>Programas de exemplo</translation>
    </message>
    <message>
        <source>Examples…</source>
        <translation>Exemplos…</translation>
    </message>
    <message>
        <source>Feed scale</source>
        <translation>Escala de avanço</translation>
    </message>
    <message>
        <source>Max accel. (mm/s²)</source>
        <translation>Acel. máx (mm/s²)</translation>
    </message>
    <message>
        <source>Max jerk (mm/s³)</source>
        <translation>Jerk máx (mm/s³)</translation>
    </message>
    <message>
        <source>Open a G-code program</source>
        <translation>Abrir um programa G-code</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.ngc *.gcode *.tap);;All files (*)</source>
        <translation>Programas G-code (*.nc *.ngc *.gcode *.tap);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Open a program or pick an example.</source>
        <translation>Abra um programa ou escolha um exemplo.</translation>
    </message>
    <message numerus="yes">
        <source>%n motion block(s), %1 mm, run %2 s</source>
        <translation>
            <numerusform>%n bloco de movimento, %1 mm, execução %2 s</numerusform>
            <numerusform>%n blocos de movimento, %1 mm, execução %2 s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>, %n sharp corner(s)</source>
        <translation>
            <numerusform>, %n canto vivo</numerusform>
            <numerusform>, %n cantos vivos</numerusform>
        </translation>
    </message>
    <message>
        <source>; one full circle: ISO 230-4 test</source>
        <translation>; um círculo completo: ensaio ISO 230-4</translation>
    </message>
    <message numerus="yes">
        <source>; %n warning(s)</source>
        <translation>
            <numerusform>; %n aviso</numerusform>
            <numerusform>; %n avisos</numerusform>
        </translation>
    </message>
    <message>
        <source>cubic move</source>
        <translation>movimento cúbico</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>círculo</translation>
    </message>
    <message>
        <source>The plots still show the session&apos;s %1: a G-code trajectory needs a program (Open… or pick an example).</source>
        <translation>Os gráficos ainda mostram o %1 da sessão: uma trajetória G-code precisa de um programa (Abrir… ou escolha um exemplo).</translation>
    </message>
    <message>
        <source>The plots still show the session&apos;s %1: the trajectory chosen in the editor is not valid yet (see the field marked red).</source>
        <translation>Os gráficos ainda mostram o %1 da sessão: a trajetória escolhida no editor ainda não é válida (veja o campo marcado em vermelho).</translation>
    </message>
    <message>
        <source>no program: open one or pick an example</source>
        <translation>nenhum programa: abra um ou escolha um exemplo</translation>
    </message>
    <message>
        <source>tf: must be later than t0</source>
        <translation>tf: deve ser posterior a t0</translation>
    </message>
    <message>
        <source>%1: a %2 s run at dt = %3 s needs %4 samples; at most %5 fit in memory</source>
        <translation>%1: uma simulação de %2 s com dt = %3 s precisa de %4 amostras; cabem no máximo %5 na memória</translation>
    </message>
    <message>
        <source>a %1 s run at dt = %2 s needs %3 samples; at most %4 fit in memory</source>
        <translation>uma simulação de %1 s com dt = %2 s precisa de %3 amostras; cabem no máximo %4 na memória</translation>
    </message>
    <message>
        <source>The commanded motion both axes follow: a point-to-point move, a circle (x = R sin ωt, y = R cos ωt) or a G-code program along its feed profile</source>
        <translation>O movimento comandado que os dois eixos seguem: um movimento ponto a ponto, um círculo (x = R sin ωt, y = R cos ωt) ou um programa G-code ao longo do seu perfil de avanço</translation>
    </message>
    <message>
        <source>The example programs shipped with XY Tune (circles, a square, a star, an engraving): choose one to load it as the program</source>
        <translation>Os programas de exemplo que acompanham o XY Tune (círculos, um quadrado, uma estrela, uma gravação): escolha um para carregá-lo como programa</translation>
    </message>
    <message>
        <source>Start position x0 (mm) of the point-to-point move, held before t0</source>
        <translation>Posição inicial x0 (mm) do movimento ponto a ponto, mantida antes de t0</translation>
    </message>
    <message>
        <source>End position xf (mm) of the point-to-point move, reached at tf</source>
        <translation>Posição final xf (mm) do movimento ponto a ponto, atingida em tf</translation>
    </message>
    <message>
        <source>Start time t0 (s) of the move</source>
        <translation>Instante inicial t0 (s) do movimento</translation>
    </message>
    <message>
        <source>End time tf (s) of the move: the cubic (or quintic) joins x0 at t0 to xf at tf with the end velocities v0, vf (Braga et al. Eq. 4–6)</source>
        <translation>Instante final tf (s) do movimento: a cúbica (ou quíntica) liga x0 em t0 a xf em tf com as velocidades nas extremidades v0, vf (Braga et al., Eq. 4–6)</translation>
    </message>
    <message>
        <source>Velocity v0 (mm/s) at the start of the move</source>
        <translation>Velocidade v0 (mm/s) no início do movimento</translation>
    </message>
    <message>
        <source>Velocity vf (mm/s) at the end of the move</source>
        <translation>Velocidade vf (mm/s) no fim do movimento</translation>
    </message>
    <message>
        <source>Radius R (mm) of the circle x = R sin ωt, y = R cos ωt</source>
        <translation>Raio R (mm) do círculo x = R sin ωt, y = R cos ωt</translation>
    </message>
    <message>
        <source>Angular speed ω (rad/s) of the circle: one revolution takes 2π/ω seconds</source>
        <translation>Velocidade angular ω (rad/s) do círculo: uma volta leva 2π/ω segundos</translation>
    </message>
    <message>
        <source>Ramp-in (s): the circle&apos;s speed rises smoothly from 0 to ω over this time, so the axes do not start with a step in velocity</source>
        <translation>Rampa de entrada (s): a velocidade do círculo sobe suavemente de 0 a ω nesse tempo, para que os eixos não partam com um degrau de velocidade</translation>
    </message>
    <message>
        <source>Feed scale: the feed override applied to every F word of the program (1 = as programmed)</source>
        <translation>Escala de avanço: o ajuste de avanço (feed override) aplicado a cada palavra F do programa (1 = como programado)</translation>
    </message>
    <message>
        <source>Maximum acceleration (mm/s²) of the feed profile along the path; on arcs v²/R stays below it too</source>
        <translation>Aceleração máxima (mm/s²) do perfil de avanço ao longo do percurso; nos arcos, v²/R também fica abaixo dela</translation>
    </message>
    <message>
        <source>Simulation step dt (s): the continuous runs are sampled at it (and a G-code program&apos;s profile is planned at it)</source>
        <translation>Passo de simulação dt (s): as simulações contínuas são amostradas com ele (e o perfil de um programa G-code é planejado com ele)</translation>
    </message>
    <message>
        <source>Maximum jerk (mm/s³) of the feed profile (an S-curve); 0 = no jerk limit (a trapezoidal profile)</source>
        <translation>Jerk máximo (mm/s³) do perfil de avanço (uma curva em S); 0 = sem limite de jerk (um perfil trapezoidal)</translation>
    </message>
    <message>
        <source>The G-code program; its whole text is kept in the session, so a shared session needs no .nc file</source>
        <translation>O programa G-code; seu texto completo é guardado na sessão, de modo que uma sessão compartilhada dispensa o arquivo .nc</translation>
    </message>
    <message>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message>
        <source>must be at most 1 s</source>
        <translation>deve ser no máximo 1 s</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (0 = automatic)</source>
        <translation>deve ser &gt;= 0 (0 = automático)</translation>
    </message>
    <message>
        <source>must be at most 100000 s</source>
        <translation>deve ser no máximo 100000 s</translation>
    </message>
    <message>
        <source>must be &gt;= 0 (0 = none)</source>
        <translation>deve ser &gt;= 0 (0 = nenhum)</translation>
    </message>
</context>
<context>
    <name>xyt::ui::TuningSession</name>
    <message>
        <source>axis %1, %2</source>
        <translation>eixo %1, %2</translation>
    </message>
    <message>
        <source>%1: %2; %3: %4</source>
        <translation>%1: %2; %3: %4</translation>
    </message>
    <message>
        <source>Set ωn of %1 to %2</source>
        <translation>Definir ωn de %1 como %2</translation>
    </message>
    <message>
        <source>Set kp of %1 to %2</source>
        <translation>Definir kp de %1 como %2</translation>
    </message>
    <message>
        <source>Change the plant of %1</source>
        <translation>Alterar a planta de %1</translation>
    </message>
    <message>
        <source>Change the model unit of %1</source>
        <translation>Alterar a unidade do modelo de %1</translation>
    </message>
    <message>
        <source>Change the friction of %1</source>
        <translation>Alterar o atrito de %1</translation>
    </message>
    <message>
        <source>Change the flexible mode and notch of %1</source>
        <translation>Alterar o modo flexível e o notch de %1</translation>
    </message>
    <message>
        <source>Change the trajectory</source>
        <translation>Alterar a trajetória</translation>
    </message>
    <message>
        <source>Change the cross-coupling</source>
        <translation>Alterar o acoplamento cruzado</translation>
    </message>
    <message>
        <source>Switch the cross-coupling off</source>
        <translation>Desligar o acoplamento cruzado</translation>
    </message>
    <message>
        <source>Set the actuator limit to %1 V</source>
        <translation>Definir o limite do atuador como %1 V</translation>
    </message>
    <message>
        <source>Change the digital implementation</source>
        <translation>Alterar a implementação digital</translation>
    </message>
    <message>
        <source>Set the controller sample time to %1 s</source>
        <translation>Definir o período de amostragem do controlador como %1 s</translation>
    </message>
    <message>
        <source>Change the PI discretization</source>
        <translation>Alterar a discretização do PI</translation>
    </message>
    <message>
        <source>Change the specification</source>
        <translation>Alterar a especificação</translation>
    </message>
    <message>
        <source>Store snapshot %1</source>
        <translation>Guardar instantâneo %1</translation>
    </message>
    <message>
        <source>Use loop gain %1 from the root locus</source>
        <translation>Usar o ganho de malha %1 do lugar das raízes</translation>
    </message>
    <message>
        <source>Only a PID + feedforward axis has zeros of its own to drag.</source>
        <translation>Só um eixo PID + pré-alimentação tem zeros próprios para arrastar.</translation>
    </message>
    <message>
        <source>Move a zero of %1&apos;s PID</source>
        <translation>Mover um zero do PID de %1</translation>
    </message>
    <message>
        <source>Change the design method</source>
        <translation>Alterar o método de projeto</translation>
    </message>
    <message>
        <source>Change the pole-placement design</source>
        <translation>Alterar o projeto por alocação de polos</translation>
    </message>
</context>
<context>
    <name>xyt::ui::UserGuideWindow</name>
    <message>
        <source>XY Tune user guide</source>
        <translation>Guia do usuário do XY Tune</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Voltar</translation>
    </message>
    <message>
        <source>Back to the page shown before (Alt+Left)</source>
        <translation>Voltar à página mostrada antes (Alt+Left)</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Avançar</translation>
    </message>
    <message>
        <source>Forward to the page left with Back (Alt+Right)</source>
        <translation>Avançar para a página deixada com Voltar (Alt+Right)</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Início</translation>
    </message>
    <message>
        <source>The guide&apos;s first page: the list of tutorials</source>
        <translation>A primeira página do guia: a lista de tutoriais</translation>
    </message>
    <message>
        <source>The pages of the guide: the tutorials, then the reference pages (command line, session file, exports, equations, architecture)</source>
        <translation>As páginas do guia: os tutoriais e depois as páginas de referência (linha de comando, arquivo de sessão, exportações, equações, arquitetura)</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Guia do usuário</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referência</translation>
    </message>
    <message>
        <source>%1 – XY Tune user guide</source>
        <translation>%1 – Guia do usuário do XY Tune</translation>
    </message>
    <message>
        <source># No pages

This build of XY Tune holds no documentation pages (the folder docs/ was empty when it was built).</source>
        <translation># Nenhuma página

Esta compilação do XY Tune não contém páginas de documentação (a pasta docs/ estava vazia quando ela foi compilada).</translation>
    </message>
</context>
<context>
    <name>xyt::ui::VibrationPlot</name>
    <message>
        <source>Vibration</source>
        <translation>Vibração</translation>
    </message>
    <message>
        <source>frequency (Hz)</source>
        <translation>frequência (Hz)</translation>
    </message>
    <message>
        <source>|G| (dB re mm/V)</source>
        <translation>|G| (dB ref. mm/V)</translation>
    </message>
    <message>
        <source>frequency of the mode (Hz)</source>
        <translation>frequência do modo (Hz)</translation>
    </message>
    <message>
        <source>residual (%)</source>
        <translation>residual (%)</translation>
    </message>
    <message>
        <source>rigid |G|</source>
        <translation>|G| rígido</translation>
    </message>
    <message>
        <source>with the mode</source>
        <translation>com o modo</translation>
    </message>
    <message>
        <source>notch |N|</source>
        <translation>notch |N|</translation>
    </message>
    <message>
        <source>measured |H|</source>
        <translation>|H| medido</translation>
    </message>
    <message>
        <source>PSD (dB)</source>
        <translation>DEP (dB)</translation>
    </message>
    <message>
        <source>accel. PSD</source>
        <translation>DEP da acel.</translation>
    </message>
    <message>
        <source>input shaper</source>
        <translation>modelador de entrada</translation>
    </message>
    <message>
        <source>5 % tolerance</source>
        <translation>tolerância de 5 %</translation>
    </message>
    <message>
        <source>|H| measured from %1, drawn where γ² ≥ %2</source>
        <translation>|H| medido de %1, desenhado onde γ² ≥ %2</translation>
    </message>
    <message>
        <source>PSD of %1</source>
        <translation>DEP de %1</translation>
    </message>
    <message>
        <source>mode %1 Hz</source>
        <translation>modo %1 Hz</translation>
    </message>
    <message>
        <source>notch %1 Hz</source>
        <translation>notch %1 Hz</translation>
    </message>
    <message>
        <source>measured %1 Hz</source>
        <translation>medido %1 Hz</translation>
    </message>
    <message>
        <source>, ζ %1</source>
        <translation>, ζ %1</translation>
    </message>
    <message>
        <source>%1 %2 Hz, ζ %3</source>
        <translation>%1 %2 Hz, ζ %3</translation>
    </message>
    <message>
        <source>%1 % left at %2 Hz</source>
        <translation>%1 % restante em %2 Hz</translation>
    </message>
    <message>
        <source>No input shaper: the Mode fold&apos;s Input shaper sets one</source>
        <translation>Sem modelador de entrada: o Modelador de entrada da seção Modo define um</translation>
    </message>
    <message>
        <source>no input shaper</source>
        <translation>sem modelador de entrada</translation>
    </message>
    <message>
        <source>The table is rigid: set a flexible mode in the Design box&apos;s Mode fold</source>
        <translation>A mesa é rígida: defina um modo flexível na seção Modo da caixa Projeto</translation>
    </message>
    <message>
        <source>Vibration: the rigid plant, the plant with its flexible mode and the notch (mm/V against Hz), the input shaper&apos;s sensitivity curve with the 5 % tolerance, and the residual vibration of the run&apos;s move shaped and unshaped.</source>
        <translation>Vibração: a planta rígida, a planta com seu modo flexível e o notch (mm/V em função de Hz), a curva de sensibilidade do modelador de entrada com a tolerância de 5 %, e a vibração residual do movimento simulado com e sem modelagem.</translation>
    </message>
</context>
<context>
    <name>xyt::ui::VibrationView</name>
    <message>
        <source>Vibration of %1</source>
        <translation>Vibração de %1</translation>
    </message>
    <message>
        <source>%1 shaper: %2 impulses over %3 ms, a delay of %4 ms</source>
        <translation>modelador %1: %2 impulsos em %3 ms, um atraso de %4 ms</translation>
    </message>
    <message>
        <source>; the %1 Hz mode%2 rings %3 with an amplitude of %4 mm shaped, %5 mm unshaped</source>
        <translation>; o modo de %1 Hz%2 oscila %3 com amplitude de %4 mm com modelagem, %5 mm sem modelagem</translation>
    </message>
    <message>
        <source> it is designed for</source>
        <translation> para o qual foi projetado</translation>
    </message>
    <message>
        <source>after the move</source>
        <translation>após o movimento</translation>
    </message>
    <message>
        <source>along the path</source>
        <translation>ao longo do percurso</translation>
    </message>
</context>
<context>
    <name>xyt::ui::WelcomeDialog</name>
    <message>
        <source>Welcome to XY Tune</source>
        <translation>Bem-vindo ao XY Tune</translation>
    </message>
    <message>
        <source>XY Tune tunes the position controllers of two-axis XY tables. Start with a tutorial (it opens in the user guide, F1) or open an example session in the workbench.</source>
        <translation>O XY Tune sintoniza os controladores de posição de mesas XY de dois eixos. Comece por um tutorial (ele abre no guia do usuário, F1) ou abra uma sessão de exemplo na bancada.</translation>
    </message>
    <message>
        <source>Tutorials</source>
        <translation>Tutoriais</translation>
    </message>
    <message>
        <source>The user guide&apos;s tutorials: double-click one to read it in the user guide window</source>
        <translation>Os tutoriais do guia do usuário: dê um clique duplo em um deles para lê-lo na janela do guia do usuário</translation>
    </message>
    <message>
        <source>The user guide: contents</source>
        <translation>O guia do usuário: sumário</translation>
    </message>
    <message>
        <source>The user guide (reference pages)</source>
        <translation>O guia do usuário (páginas de referência)</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Ler</translation>
    </message>
    <message>
        <source>Open the selected tutorial in the user guide</source>
        <translation>Abrir o tutorial selecionado no guia do usuário</translation>
    </message>
    <message>
        <source>Example sessions</source>
        <translation>Sessões de exemplo</translation>
    </message>
    <message>
        <source>Example sessions shipped with XY Tune: double-click one to open it in the workbench (as File › Open would)</source>
        <translation>Sessões de exemplo que acompanham o XY Tune: dê um clique duplo em uma delas para abri-la na bancada (como faria Arquivo › Abrir)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>No example sessions were found in %1</source>
        <translation>Nenhuma sessão de exemplo foi encontrada em %1</translation>
    </message>
    <message>
        <source>(no examples folder)</source>
        <translation>(sem pasta de exemplos)</translation>
    </message>
    <message>
        <source>Open session</source>
        <translation>Abrir sessão</translation>
    </message>
    <message>
        <source>Open the selected example in the workbench</source>
        <translation>Abrir o exemplo selecionado na bancada</translation>
    </message>
    <message>
        <source>Its tutorial</source>
        <translation>Seu tutorial</translation>
    </message>
    <message>
        <source>Read the tutorial that walks through the selected example</source>
        <translation>Ler o tutorial que percorre o exemplo selecionado</translation>
    </message>
    <message>
        <source>Show at start</source>
        <translation>Mostrar ao iniciar</translation>
    </message>
    <message>
        <source>Show this page each time XY Tune starts (it is always in Help › Tutorials)</source>
        <translation>Mostrar esta página sempre que o XY Tune iniciar (ela está sempre em Ajuda › Tutoriais)</translation>
    </message>
</context>
<context>
    <name>zero</name>
    <message>
        <source>must be nonzero</source>
        <translation>deve ser diferente de zero</translation>
    </message>
</context>
</TS>
