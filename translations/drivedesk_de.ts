<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>Acknowledge</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>not ready</source>
        <translation>nicht bereit</translation>
    </message>
    <message>
        <source>address or password invalid</source>
        <translation>Adresse oder Passwort ungültig</translation>
    </message>
    <message>
        <source>data invalid</source>
        <translation>Daten ungültig</translation>
    </message>
    <message>
        <source>parameter write protected</source>
        <translation>Parameter schreibgeschützt</translation>
    </message>
    <message>
        <source>BCC error</source>
        <translation>BCC-Fehler</translation>
    </message>
    <message>
        <source>inverter busy</source>
        <translation>Umrichter beschäftigt</translation>
    </message>
    <message>
        <source>service not available</source>
        <translation>Dienst nicht verfügbar</translation>
    </message>
    <message>
        <source>password invalid</source>
        <translation>Passwort ungültig</translation>
    </message>
    <message>
        <source>telegram framing error: wrong count of characters</source>
        <translation>Telegramm-Rahmenfehler: falsche Zeichenanzahl</translation>
    </message>
    <message>
        <source>transmission error: overrun, framing or parity error</source>
        <translation>Übertragungsfehler: Überlauf-, Rahmen- oder Paritätsfehler</translation>
    </message>
    <message>
        <source>set selection invalid</source>
        <translation>Satzkennung ungültig</translation>
    </message>
    <message>
        <source>language selection invalid</source>
        <translation>Sprachkennung ungültig</translation>
    </message>
    <message>
        <source>address invalid</source>
        <translation>Adresse ungültig</translation>
    </message>
    <message>
        <source>operation not possible</source>
        <translation>Operation nicht möglich</translation>
    </message>
    <message>
        <source>unknown acknowledge 15</source>
        <translation>unbekannte Quittung 15</translation>
    </message>
</context>
<context>
    <name>BackupCommit</name>
    <message>
        <source>%1: backup, %2 changed</source>
        <translation>%1: Sicherung, %2 geändert</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>BackupRepository</name>
    <message>
        <source>cannot make the directory %1</source>
        <translation>das Verzeichnis %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>the directory %1 does not exist</source>
        <translation>das Verzeichnis %1 gibt es nicht</translation>
    </message>
    <message>
        <source>%1 is not a git repository of backups: make it one with plant backup --commit</source>
        <translation>%1 ist kein Git-Repository mit Sicherungen: plant backup --commit macht es zu einem</translation>
    </message>
    <message>
        <source>there is no revision on or before %1 in %2</source>
        <translation>in %2 gibt es keine Revision bis einschließlich %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no revision of %2: give a commit id, a tag or a date like 2026-11-24</source>
        <translation>„%1“ ist keine Revision von %2: eine Commit-ID, ein Tag oder ein Datum wie 2026-11-24 angeben</translation>
    </message>
    <message>
        <source>git cat-file: no object %1</source>
        <translation>git cat-file: kein Objekt %1</translation>
    </message>
    <message>
        <source>cannot make a temporary folder: %1</source>
        <translation>ein temporärer Ordner kann nicht angelegt werden: %1</translation>
    </message>
</context>
<context>
    <name>ChosenValues</name>
    <message>
        <source>%1: the target has no such parameter</source>
        <translation>%1: das Ziel hat diesen Parameter nicht</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>CliJournalText</name>
    <message>
        <source>no journal yet at %1: nothing was written</source>
        <translation>noch kein Journal unter %1: nichts wurde geschrieben</translation>
    </message>
</context>
<context>
    <name>CliPlantHistory</name>
    <message>
        <source>no revision</source>
        <translation>keine Revision</translation>
    </message>
    <message>
        <source>no drive saved: nothing committed</source>
        <translation>kein Umrichter gesichert: kein Commit angelegt</translation>
    </message>
    <message>
        <source>no setting changed since the last commit: nothing committed</source>
        <translation>seit dem letzten Commit keine Einstellung geändert: kein Commit angelegt</translation>
    </message>
    <message>
        <source>committed %1: %2</source>
        <translation>Commit %1 angelegt: %2</translation>
    </message>
</context>
<context>
    <name>CliSpectrum</name>
    <message>
        <source>%1 in &apos;%2&apos;, %3 to %4 ms</source>
        <translation>%1 in &apos;%2&apos;, %3 bis %4 ms</translation>
    </message>
    <message>
        <source>%1 samples at %2 Hz, %3 Hz a bin</source>
        <translation>%1 Abtastwerte mit %2 Hz, %3 Hz je Bin</translation>
    </message>
    <message>
        <source>; they came unevenly and were resampled to even spacing</source>
        <translation>; sie kamen ungleichmäßig und wurden auf gleiche Abstände umgerechnet</translation>
    </message>
    <message>
        <source>no peaks: the channel is flat in the window</source>
        <translation>keine Spitzen: der Kanal ist im Fenster flach</translation>
    </message>
    <message>
        <source>frequency [Hz]</source>
        <translation>Frequenz [Hz]</translation>
    </message>
    <message>
        <source>amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>amplitude [%1]</source>
        <translation>Amplitude [%1]</translation>
    </message>
    <message>
        <source>&apos;%1&apos; holds no samples</source>
        <translation>&apos;%1&apos; enthält keine Abtastwerte</translation>
    </message>
    <message>
        <source>&apos;%1&apos; fits several channels of &apos;%2&apos;: give its title or number (%3)</source>
        <translation>&apos;%1&apos; passt zu mehreren Kanälen von &apos;%2&apos;: Titel oder Nummer angeben (%3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no channel &apos;%2&apos;; it holds %3</source>
        <translation>&apos;%1&apos; hat keinen Kanal &apos;%2&apos;; es enthält %3</translation>
    </message>
    <message>
        <source>%1 %2 ms is outside the recording in &apos;%3&apos; (%4 to %5 ms)</source>
        <translation>%1 %2 ms liegt außerhalb der Aufzeichnung in &apos;%3&apos; (%4 bis %5 ms)</translation>
    </message>
</context>
<context>
    <name>ComparisonTable</name>
    <message>
        <source>equal</source>
        <translation>gleich</translation>
    </message>
    <message>
        <source>different</source>
        <translation>verschieden</translation>
    </message>
    <message>
        <source>only in A</source>
        <translation>nur in A</translation>
    </message>
    <message>
        <source>only in B</source>
        <translation>nur in B</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>schreibgeschützt</translation>
    </message>
    <message>
        <source>not a setting</source>
        <translation>keine Einstellung</translation>
    </message>
</context>
<context>
    <name>ConnectionOptions</name>
    <message>
        <source>--%1 %2: expected a number from %3 to %4</source>
        <translation>--%1 %2: erwartet wird eine Zahl von %3 bis %4</translation>
    </message>
    <message>
        <source>unknown language &quot;%1&quot;: use en or de</source>
        <translation>unbekannte Sprache „%1“: en oder de angeben</translation>
    </message>
    <message>
        <source>--connect is missing: give tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>--connect fehlt: tcp:HOST:PORT, serial:GERÄT oder sim angeben</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;: use hsp5, din66019ii or din66019</source>
        <translation>unbekanntes Protokoll „%1“: hsp5, din66019ii oder din66019 angeben</translation>
    </message>
    <message>
        <source>--hsp5-extensions needs --protocol hsp5</source>
        <translation>--hsp5-extensions verlangt --protocol hsp5</translation>
    </message>
</context>
<context>
    <name>ConnectionSettingsText</name>
    <message>
        <source>&quot;%1&quot; is not HOST:PORT (an IPv6 address is written [ADDRESS]:PORT)</source>
        <translation>„%1“ ist nicht HOST:PORT (eine IPv6-Adresse wird [ADRESSE]:PORT geschrieben)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no port: write tcp:HOST:PORT</source>
        <translation>„%1“ hat keinen Port: tcp:HOST:PORT angeben</translation>
    </message>
    <message>
        <source>the host is missing in &quot;%1&quot;: write tcp:HOST:PORT</source>
        <translation>in „%1“ fehlt der Host: tcp:HOST:PORT angeben</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a TCP port (1..65535)</source>
        <translation>„%1“ ist kein TCP-Port (1..65535)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the simulated drive takes no further address (write sim)</source>
        <translation>„%1“: der simulierte Umrichter braucht keine weitere Adresse (sim angeben)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no serial device: write serial:/dev/ttyUSB0 or serial:COM3</source>
        <translation>„%1“ nennt keine serielle Schnittstelle: serial:/dev/ttyUSB0 oder serial:COM3 angeben</translation>
    </message>
    <message>
        <source>unknown connection &quot;%1&quot;: expected tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>unbekannte Verbindung „%1“: erwartet wird tcp:HOST:PORT, serial:GERÄT oder sim</translation>
    </message>
    <message>
        <source>simulated %1 drive</source>
        <translation>simulierter %1-Umrichter</translation>
    </message>
    <message>
        <source>%1 on %2 (%3 %4)</source>
        <translation>%1 an %2 (%3 %4)</translation>
    </message>
    <message>
        <source>%1 via %2</source>
        <translation>%1 über %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a TCP port (0..65535, 0 picks a free one)</source>
        <translation>„%1“ ist kein TCP-Port (0..65535, 0 wählt einen freien)</translation>
    </message>
    <message>
        <source>%1 drive %2</source>
        <translation>%1 Umrichter %2</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>automatisch</translation>
    </message>
</context>
<context>
    <name>DisplayScaling</name>
    <message>
        <source>calculation mode %1</source>
        <translation>Berechnungsmodus %1</translation>
    </message>
    <message>
        <source>divisor 0</source>
        <translation>Divisor 0</translation>
    </message>
    <message>
        <source>%1 (no scaling: %2)</source>
        <translation>%1 (keine Normierung: %2)</translation>
    </message>
    <message>
        <source>%1 (no scaling: value + offset is 0)</source>
        <translation>%1 (keine Normierung: Wert + Offset ist 0)</translation>
    </message>
    <message>
        <source>no value given</source>
        <translation>kein Wert angegeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be converted: the scaling of this parameter is invalid (%2)</source>
        <translation>„%1“ kann nicht umgerechnet werden: die Normierung dieses Parameters ist ungültig (%2)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>unit &apos;%1&apos; does not match: this value has no unit</source>
        <translation>Einheit „%1“ passt nicht: dieser Wert hat keine Einheit</translation>
    </message>
    <message>
        <source>unit &apos;%1&apos; does not match &apos;%2&apos;</source>
        <translation>Einheit „%1“ passt nicht zu „%2“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a hexadecimal number</source>
        <translation>„%1“ ist keine Hexadezimalzahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not fit in 32 bits</source>
        <translation>„%1“ passt nicht in 32 Bit</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has too many digits</source>
        <translation>„%1“ hat zu viele Stellen</translation>
    </message>
    <message>
        <source>every raw value shows 0 in this scaling (multiplier 0): the raw value cannot be chosen</source>
        <translation>bei dieser Normierung zeigt jeder Rohwert 0 (Multiplikator 0): der Rohwert lässt sich nicht bestimmen</translation>
    </message>
    <message>
        <source>no raw value gives %1 in this scaling</source>
        <translation>kein Rohwert ergibt bei dieser Normierung %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range</source>
        <translation>„%1“ liegt außerhalb des Wertebereichs</translation>
    </message>
    <message>
        <source>no raw value gives 0 in this scaling</source>
        <translation>kein Rohwert ergibt bei dieser Normierung 0</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range: it needs raw value %2, beyond 32 bits</source>
        <translation>„%1“ liegt außerhalb des Wertebereichs: dafür wäre der Rohwert %2 nötig, jenseits von 32 Bit</translation>
    </message>
</context>
<context>
    <name>DownloadPlan</name>
    <message>
        <source>the file was made for &quot;%1&quot;, the drive is &quot;%2&quot;</source>
        <translation>die Datei wurde für &quot;%1&quot; erstellt, der Umrichter ist &quot;%2&quot;</translation>
    </message>
    <message>
        <source>the drive&apos;s identification could not be read, so the file cannot be checked against it</source>
        <translation>die Kennung des Umrichters konnte nicht gelesen werden, daher kann die Datei nicht mit ihm verglichen werden</translation>
    </message>
    <message>
        <source>the file does not say which kind of drive it was made for (its identification parameters are missing)</source>
        <translation>die Datei sagt nicht, für welche Art Umrichter sie erstellt wurde (ihre Kennungsparameter fehlen)</translation>
    </message>
    <message>
        <source>the file was made for another drive: %1 %2 is %3 in the file, %4 on the drive</source>
        <translation>die Datei wurde für einen anderen Umrichter erstellt: %1 %2 ist %3 in der Datei, %4 am Umrichter</translation>
    </message>
    <message>
        <source>the file was made for another kind of drive</source>
        <translation>die Datei wurde für eine andere Art Umrichter erstellt</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) of the file are not on the drive: %1</source>
        <translation>
            <numerusform>%n Parameter der Datei gibt es am Umrichter nicht: %1</numerusform>
            <numerusform>%n Parameter der Datei gibt es am Umrichter nicht: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) of the drive are not in the file: %1</source>
        <translation>
            <numerusform>%n Parameter des Umrichters fehlt in der Datei: %1</numerusform>
            <numerusform>%n Parameter des Umrichters fehlen in der Datei: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>one value for all sets, left out by the sets chosen</source>
        <translation>ein Wert für alle Sätze, durch die gewählten Sätze ausgelassen</translation>
    </message>
    <message>
        <source>needs password level %1</source>
        <translation>erfordert Passwortebene %1</translation>
    </message>
    <message>
        <source>%1 not in the file (not read when it was made)</source>
        <translation>%1 nicht in der Datei (beim Erstellen nicht gelesen)</translation>
    </message>
    <message>
        <source>%1 (%2) %3 is outside %4 .. %5</source>
        <translation>%1 (%2) %3 liegt außerhalb %4 .. %5</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) outside the drive&apos;s limits: %1</source>
        <translation>
            <numerusform>%n Wert außerhalb der Grenzen des Umrichters: %1</numerusform>
            <numerusform>%n Werte außerhalb der Grenzen des Umrichters: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>%1  %2%3: %4 -&gt; %5%6
</source>
        <translation>%1  %2%3: %4 -&gt; %5%6
</translation>
    </message>
    <message>
        <source>  (always written)</source>
        <translation>  (wird immer geschrieben)</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) to write</source>
        <translation>
            <numerusform>%n Wert zu schreiben</numerusform>
            <numerusform>%n Werte zu schreiben</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n unchanged</source>
        <translation>
            <numerusform>%n unverändert</numerusform>
            <numerusform>%n unverändert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n left</source>
        <translation>
            <numerusform>%n ausgelassen</numerusform>
            <numerusform>%n ausgelassen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n read-only value(s) differ and are never written</source>
        <translation>
            <numerusform>%n schreibgeschützter Wert weicht ab und wird nie geschrieben</numerusform>
            <numerusform>%n schreibgeschützte Werte weichen ab und werden nie geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <source>group %1 %2</source>
        <translation>Gruppe %1 %2</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 is in the file, not on the drive</source>
        <translation>%1 ist in der Datei, nicht im Umrichter</translation>
    </message>
    <message>
        <source>%1 is on the drive, not in the file</source>
        <translation>%1 ist im Umrichter, nicht in der Datei</translation>
    </message>
    <message>
        <source>%1: %2 is %3 in the file, %4 on the drive</source>
        <translation>%1: %2 ist %3 in der Datei, %4 im Umrichter</translation>
    </message>
    <message>
        <source>the drive has no identification, and the file&apos;s metadata is not the drive&apos;s: %1</source>
        <translation>der Umrichter hat keine Kennung, und die Metadaten der Datei sind nicht die des Umrichters: %1</translation>
    </message>
</context>
<context>
    <name>DownloadReport</name>
    <message>
        <source>the value</source>
        <translation>der Wert</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
    <message>
        <source>not sent: %1</source>
        <translation>nicht gesendet: %1</translation>
    </message>
    <message>
        <source>%1 not sent: %2</source>
        <translation>%1 nicht gesendet: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written and read back</source>
        <translation>
            <numerusform>%n Wert geschrieben und zurückgelesen</numerusform>
            <numerusform>%n Werte geschrieben und zurückgelesen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n unchanged</source>
        <translation>
            <numerusform>%n unverändert</numerusform>
            <numerusform>%n unverändert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n refused</source>
        <translation>
            <numerusform>%n abgelehnt</numerusform>
            <numerusform>%n abgelehnt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n skipped</source>
        <translation>
            <numerusform>%n ausgelassen</numerusform>
            <numerusform>%n ausgelassen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n not written</source>
        <translation>
            <numerusform>%n nicht geschrieben</numerusform>
            <numerusform>%n nicht geschrieben</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n read-only value(s) of the file differ from the drive&apos;s; they are never written</source>
        <translation>
            <numerusform>%n schreibgeschützter Wert der Datei weicht vom Umrichter ab; er wird nie geschrieben</numerusform>
            <numerusform>%n schreibgeschützte Werte der Datei weichen vom Umrichter ab; sie werden nie geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <source>The download stopped: %1</source>
        <translation>Der Download wurde abgebrochen: %1</translation>
    </message>
    <message>
        <source>Written:</source>
        <translation>Geschrieben:</translation>
    </message>
    <message>
        <source>Refused:</source>
        <translation>Abgelehnt:</translation>
    </message>
    <message>
        <source>Skipped:</source>
        <translation>Ausgelassen:</translation>
    </message>
    <message>
        <source>Not written:</source>
        <translation>Nicht geschrieben:</translation>
    </message>
    <message>
        <source>written %1, but %2 holds %3</source>
        <translation>%1 geschrieben, aber %2 enthält %3</translation>
    </message>
    <message>
        <source>%1: no answer, so whether the drive took %2 is unknown (%3)</source>
        <translation>%1: keine Antwort, daher ist unbekannt, ob der Umrichter %2 übernommen hat (%3)</translation>
    </message>
    <message>
        <source>%1: the drive acknowledged %2, but it could not be read back (%3)</source>
        <translation>%1: der Umrichter hat %2 quittiert, aber es konnte nicht zurückgelesen werden (%3)</translation>
    </message>
    <message numerus="yes">
        <source>%n unknown</source>
        <translation>
            <numerusform>%n unbekannt</numerusform>
            <numerusform>%n unbekannt</numerusform>
        </translation>
    </message>
    <message>
        <source>Unknown (sent, no answer):</source>
        <translation>Unbekannt (gesendet, keine Antwort):</translation>
    </message>
    <message>
        <source>%1: no answer to writing %2, and the drive holds %3: not written</source>
        <translation>%1: keine Antwort auf das Schreiben von %2, und der Umrichter hält %3: nicht geschrieben</translation>
    </message>
</context>
<context>
    <name>DriveChange</name>
    <message>
        <source>%1 %2: no longer on the drive (was %3)</source>
        <translation>%1 %2: nicht mehr im Umrichter (war %3)</translation>
    </message>
    <message>
        <source>%1 %2: new on the drive, %3</source>
        <translation>%1 %2: neu im Umrichter, %3</translation>
    </message>
    <message>
        <source>%1 %2: %3 -&gt; %4</source>
        <translation>%1 %2: %3 -&gt; %4</translation>
    </message>
    <message>
        <source>%1 %2 set %3: %4 -&gt; %5</source>
        <translation>%1 %2 Satz %3: %4 -&gt; %5</translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation>%1 hinzugekommen</translation>
    </message>
    <message>
        <source>%1 gone</source>
        <translation>%1 entfallen</translation>
    </message>
    <message>
        <source>%1: the file cannot be read: %2</source>
        <translation>%1: die Datei kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk</name>
    <message>
        <source>offline records of %1, one a millisecond assumed</source>
        <translation>Offline-Aufzeichnung von %1, eine je Millisekunde angenommen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::AccessController</name>
    <message>
        <source>The password level could not be read: %1</source>
        <translation>Die Passwortebene konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Password not accepted: %1</source>
        <translation>Passwort nicht angenommen: %1</translation>
    </message>
    <message>
        <source>Password accepted</source>
        <translation>Passwort angenommen</translation>
    </message>
    <message>
        <source>The password parameter reads %1, which names no password level: the level stays %2</source>
        <translation>Der Passwortparameter zeigt %1, das ist keine Passwortebene: die Ebene bleibt %2</translation>
    </message>
    <message>
        <source>Password level: %1</source>
        <translation>Passwortebene: %1</translation>
    </message>
    <message>
        <source>the connection closed before the drive answered</source>
        <translation>die Verbindung wurde geschlossen, bevor der Umrichter antwortete</translation>
    </message>
</context>
<context>
    <name>DriveDesk::AccessFeature</name>
    <message>
        <source>&amp;Password...</source>
        <translation>&amp;Passwort …</translation>
    </message>
    <message>
        <source>Enter a password to open a higher password level</source>
        <translation>Ein Passwort eingeben, um eine höhere Passwortebene freizugeben</translation>
    </message>
    <message>
        <source>The password level in force on the drive (ud.01)</source>
        <translation>Die am Umrichter gültige Passwortebene (ud.01)</translation>
    </message>
    <message>
        <source>Password level: %1</source>
        <translation>Passwortebene: %1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
</context>
<context>
    <name>DriveDesk::BaudRateSearch</name>
    <message>
        <source>%1: no drive answered at %2 Bd</source>
        <translation>%1: bei %2 Bd hat kein Umrichter geantwortet</translation>
    </message>
    <message>
        <source>%1: this program cannot open such a connection</source>
        <translation>%1: dieses Programm kann eine solche Verbindung nicht öffnen</translation>
    </message>
    <message>
        <source>looking for the drive at %1 Bd</source>
        <translation>suche den Umrichter bei %1 Bd</translation>
    </message>
</context>
<context>
    <name>DriveDesk::BitFieldEditor</name>
    <message>
        <source>Definition %1</source>
        <translation>Definition %1</translation>
    </message>
    <message>
        <source>%1 (no plaintext)</source>
        <translation>%1 (kein Klartext)</translation>
    </message>
    <message>
        <source>%1:</source>
        <translation>%1:</translation>
    </message>
    <message>
        <source>Value: %1</source>
        <translation>Wert: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::CliPlant</name>
    <message>
        <source>cannot make the directory %1</source>
        <translation>das Verzeichnis %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>the directory %1 does not exist</source>
        <translation>das Verzeichnis %1 gibt es nicht</translation>
    </message>
    <message>
        <source>stopping every link after the value on its way...</source>
        <translation>halte jede Verbindung nach dem Wert an, der unterwegs ist …</translation>
    </message>
    <message>
        <source>reading</source>
        <translation>lese</translation>
    </message>
    <message>
        <source>%1: the addresses found written</source>
        <translation>%1: die gefundenen Adressen geschrieben</translation>
    </message>
    <message>
        <source>no link answered</source>
        <translation>keine Verbindung hat geantwortet</translation>
    </message>
    <message>
        <source>gave no identification</source>
        <translation>ohne Kennung</translation>
    </message>
    <message numerus="yes">
        <source>%1: saved %2, %n parameter(s)</source>
        <translation>
            <numerusform>%1: %2 gesichert, %n Parameter</numerusform>
            <numerusform>%1: %2 gesichert, %n Parameter</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: not saved: %2: %3</source>
        <translation>%1: nicht gesichert: %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n difference(s)</source>
        <translation>
            <numerusform>%1: %n Unterschied</numerusform>
            <numerusform>%1: %n Unterschiede</numerusform>
        </translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>Satz %1</translation>
    </message>
    <message>
        <source>file %1  drive %2</source>
        <translation>Datei %1  Umrichter %2</translation>
    </message>
    <message>
        <source>only in the file</source>
        <translation>nur in der Datei</translation>
    </message>
    <message>
        <source>only on the drive</source>
        <translation>nur im Umrichter</translation>
    </message>
    <message>
        <source>checked, nothing written</source>
        <translation>geprüft, nichts geschrieben</translation>
    </message>
    <message>
        <source>downloaded or already equal</source>
        <translation>geladen oder schon gleich</translation>
    </message>
    <message>
        <source>nothing was written: %1 (--no-journal downloads without it)</source>
        <translation>es wurde nichts geschrieben: %1 (--no-journal lädt ohne Journal)</translation>
    </message>
    <message>
        <source>plant download of %1</source>
        <translation>Anlagen-Download: %1</translation>
    </message>
    <message>
        <source>--no-journal downloads without it</source>
        <translation>--no-journal lädt ohne Journal</translation>
    </message>
</context>
<context>
    <name>DriveDesk::CliRunner</name>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>keine Verbindung zu %1 möglich: %2</translation>
    </message>
    <message>
        <source>%1 (DIN66019 has no group names: give the address, e.g. 0x0203)</source>
        <translation>%1 (DIN66019 kennt keine Gruppennamen: die Adresse angeben, z. B. 0x0203)</translation>
    </message>
    <message>
        <source>%1 = %2 (raw)</source>
        <translation>%1 = %2 (Rohwert)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a raw 16-bit value (DIN66019 writes raw values)</source>
        <translation>„%1“ ist kein 16-Bit-Rohwert (DIN66019 schreibt Rohwerte)</translation>
    </message>
    <message>
        <source>metadata from the cache of this kind of drive (%1); --no-cache reads it from the drive</source>
        <translation>Metadaten aus dem Cache dieser Umrichterart (%1); --no-cache liest sie vom Umrichter</translation>
    </message>
    <message>
        <source>could not read the groups: %1</source>
        <translation>die Gruppen konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>scan incomplete: %1</source>
        <translation>Einlesen unvollständig: %1</translation>
    </message>
    <message>
        <source>the drive has no parameter %1</source>
        <translation>der Umrichter hat keinen Parameter %1</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>Satz %1</translation>
    </message>
    <message>
        <source>active set</source>
        <translation>aktiver Satz</translation>
    </message>
    <message>
        <source>%1  %2 = %3  (raw %4, %5)</source>
        <translation>%1  %2 = %3  (Rohwert %4, %5)</translation>
    </message>
    <message>
        <source>%1: %2; nothing was written</source>
        <translation>%1: %2; nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>password not accepted: %1</source>
        <translation>Passwort nicht angenommen: %1</translation>
    </message>
    <message>
        <source>password level in force: %1</source>
        <translation>gültige Passwortebene: %1</translation>
    </message>
    <message>
        <source>could not read the drive: %1</source>
        <translation>der Umrichter konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>DIN66019 carries parameter values only; use --protocol din66019ii for anything but read and write</source>
        <translation>DIN66019 überträgt nur Parameterwerte; für alles außer read und write --protocol din66019ii verwenden</translation>
    </message>
    <message>
        <source>stopping after the value on its way...</source>
        <translation>Abbruch nach dem Wert, der gerade unterwegs ist …</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n parameter(s)</source>
        <translation>
            <numerusform>%1: %n Parameter</numerusform>
            <numerusform>%1: %n Parameter</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s)</source>
        <translation>
            <numerusform>%n Wert</numerusform>
            <numerusform>%n Werte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n write-only with the default</source>
        <translation>
            <numerusform>%n nur schreibbarer mit dem Vorgabewert</numerusform>
            <numerusform>%n nur schreibbare mit dem Vorgabewert</numerusform>
        </translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>refused: %1</source>
        <translation>abgelehnt: %1</translation>
    </message>
    <message>
        <source>nothing was written; --force writes the file all the same</source>
        <translation>es wurde nichts geschrieben; --force schreibt die Datei trotzdem</translation>
    </message>
    <message>
        <source>skipped  %1  %2: %3</source>
        <translation>ausgelassen  %1  %2: %3</translation>
    </message>
    <message>
        <source>the download did not write everything; the report says what the drive holds</source>
        <translation>der Download hat nicht alles geschrieben; der Bericht sagt, was der Umrichter enthält</translation>
    </message>
    <message>
        <source>dry run: %1; nothing was written</source>
        <translation>Probelauf: %1; es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>the drive could not be read: %1</source>
        <translation>der Umrichter konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>the channels could not be assigned: %1</source>
        <translation>die Kanäle konnten nicht zugewiesen werden: %1</translation>
    </message>
    <message>
        <source>every scope channel of the drive is off: choose what to record with --channels, e.g. --channels ru.3,ru.9</source>
        <translation>alle Scope-Kanäle des Umrichters sind aus: wählen Sie mit --channels, was aufgezeichnet wird, z. B. --channels ru.3,ru.9</translation>
    </message>
    <message>
        <source>recording: %1 s, %2 Hz, %3 lost, %4 failed</source>
        <translation>Aufzeichnung: %1 s, %2 Hz, %3 verloren, %4 fehlgeschlagen</translation>
    </message>
    <message>
        <source>recording %1 for %2 s; Ctrl+C stops and writes what was recorded</source>
        <translation>zeichne %1 für %2 s auf; Strg+C beendet und schreibt das Aufgezeichnete</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n sample(s) over %2 s, achieved %3 Hz</source>
        <translation>
            <numerusform>%1: %n Abtastwert über %2 s, erreicht %3 Hz</numerusform>
            <numerusform>%1: %n Abtastwerte über %2 s, erreicht %3 Hz</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 lost, %2 failed</source>
        <translation>%1 verloren, %2 fehlgeschlagen</translation>
    </message>
    <message>
        <source>the recording ended early: %1</source>
        <translation>die Aufzeichnung endete vorzeitig: %1</translation>
    </message>
    <message>
        <source>reading offline record %1 of %2</source>
        <translation>lese Offline-Datensatz %1 von %2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n offline record(s), one a millisecond assumed</source>
        <translation>
            <numerusform>%1: %n Offline-Datensatz, einer je Millisekunde angenommen</numerusform>
            <numerusform>%1: %n Offline-Datensätze, einer je Millisekunde angenommen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>warning: %n record(s) had channel 3 or 4 beyond 16 bits and hold the nearest 16-bit value</source>
        <translation>
            <numerusform>Warnung: %n Datensatz hatte Kanal 3 oder 4 jenseits von 16 Bit und enthält den nächsten 16-Bit-Wert</numerusform>
            <numerusform>Warnung: %n Datensätze hatten Kanal 3 oder 4 jenseits von 16 Bit und enthalten den nächsten 16-Bit-Wert</numerusform>
        </translation>
    </message>
    <message>
        <source>the records could not all be read: %1</source>
        <translation>die Datensätze konnten nicht alle gelesen werden: %1</translation>
    </message>
    <message>
        <source>found the drive at %1 Bd</source>
        <translation>Umrichter bei %1 Bd gefunden</translation>
    </message>
    <message>
        <source>scan</source>
        <translation>Einlesen</translation>
    </message>
    <message numerus="yes">
        <source>%1 stopped after %2 of %n parameter(s)</source>
        <translation>
            <numerusform>%1 nach %2 von %n Parameter angehalten</numerusform>
            <numerusform>%1 nach %2 von %n Parametern angehalten</numerusform>
        </translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>the drive stopped answering (%1): %2</source>
        <translation>der Umrichter antwortet nicht mehr (%1): %2</translation>
    </message>
    <message>
        <source>not read: %1</source>
        <translation>nicht gelesen: %1</translation>
    </message>
    <message>
        <source>the connection to the drive was closed</source>
        <translation>die Verbindung zum Umrichter wurde geschlossen</translation>
    </message>
    <message>
        <source>the connection to the drive was lost (%1): %2</source>
        <translation>die Verbindung zum Umrichter ging verloren (%1): %2</translation>
    </message>
    <message>
        <source>%1; nothing was written</source>
        <translation>%1; nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>%1 not written: %2 (--no-journal writes without it)</source>
        <translation>%1 nicht geschrieben: %2 (--no-journal schreibt ohne Journal)</translation>
    </message>
    <message>
        <source>write %1</source>
        <translation>%1 schreiben</translation>
    </message>
    <message>
        <source>no journal yet at %1: there is nothing to revert</source>
        <translation>noch kein Journal unter %1: es gibt nichts zurückzusetzen</translation>
    </message>
    <message>
        <source>left out: %1</source>
        <translation>ausgelassen: %1</translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation>es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>no entry of this drive to revert; nothing was written</source>
        <translation>kein Eintrag dieses Umrichters zum Zurücksetzen; es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>%1: the values before, back to the drive</source>
        <translation>%1: die Werte von vorher zurück in den Umrichter</translation>
    </message>
    <message>
        <source>nothing was written: %1 (--no-journal downloads without it)</source>
        <translation>es wurde nichts geschrieben: %1 (--no-journal lädt ohne Journal)</translation>
    </message>
    <message>
        <source>download of %1</source>
        <translation>Download: %1</translation>
    </message>
    <message>
        <source>--no-journal downloads without it</source>
        <translation>--no-journal lädt ohne Journal</translation>
    </message>
    <message>
        <source>scope channel assignment</source>
        <translation>Kanalzuweisung des Scopes</translation>
    </message>
    <message>
        <source>--no-journal writes without it</source>
        <translation>--no-journal schreibt ohne Journal</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ClientWorker</name>
    <message>
        <source>arrived before the open request was sent, ignored: %1</source>
        <translation>kam an, bevor die offene Anfrage gesendet war, ignoriert: %1</translation>
    </message>
    <message>
        <source>a request where answers are expected, ignored: %1</source>
        <translation>eine Anfrage, wo Antworten erwartet werden, ignoriert: %1</translation>
    </message>
    <message>
        <source>the answer with invoke id %1 belongs to no open request, ignored</source>
        <translation>die Antwort mit Invoke-ID %1 gehört zu keiner offenen Anfrage, ignoriert</translation>
    </message>
    <message>
        <source>the answer does not match its request (%1), not accepted</source>
        <translation>die Antwort passt nicht zu ihrer Anfrage (%1), nicht angenommen</translation>
    </message>
    <message>
        <source>line error: %1</source>
        <translation>Leitungsfehler: %1</translation>
    </message>
    <message>
        <source>inverter request: %1</source>
        <translation>Anfrage des Umrichters: %1</translation>
    </message>
    <message>
        <source>cannot answer the inverter&apos;s request: %1</source>
        <translation>die Anfrage des Umrichters kann nicht beantwortet werden: %1</translation>
    </message>
    <message>
        <source>the client was closed</source>
        <translation>der Client wurde geschlossen</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <source>the link was lost</source>
        <translation>die Verbindung ist abgebrochen</translation>
    </message>
    <message>
        <source>only requests can be sent, this is an answer</source>
        <translation>nur Anfragen können gesendet werden, dies ist eine Antwort</translation>
    </message>
    <message>
        <source>%1 has no %2 of %3</source>
        <translation>%1 kennt kein %2 für %3</translation>
    </message>
    <message>
        <source>write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>drive address %1 is outside 0..239 (240..255: groups and broadcast)</source>
        <translation>Umrichteradresse %1 liegt außerhalb von 0..239 (240..255: Gruppen und Broadcast)</translation>
    </message>
    <message>
        <source>address %1 is a group or broadcast address: no drive answers there, so it takes writes only</source>
        <translation>Adresse %1 ist eine Gruppen- oder Broadcast-Adresse: dort antwortet kein Umrichter, daher nur Schreiben möglich</translation>
    </message>
    <message>
        <source>the codec cannot encode it</source>
        <translation>der Codec kann sie nicht codieren</translation>
    </message>
    <message>
        <source>to drive %1: %2</source>
        <translation>an Umrichter %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>no request in flight was answered: one request at a time, each after %n ms of quiet line, until the drive answers again</source>
        <translation>
            <numerusform>keine der laufenden Anfragen wurde beantwortet: eine Anfrage nach der anderen, jede nach %n ms Ruhe auf der Leitung, bis der Umrichter wieder antwortet</numerusform>
            <numerusform>keine der laufenden Anfragen wurde beantwortet: eine Anfrage nach der anderen, jede nach %n ms Ruhe auf der Leitung, bis der Umrichter wieder antwortet</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: this program cannot open such a connection</source>
        <translation>%1: dieses Programm kann eine solche Verbindung nicht öffnen</translation>
    </message>
    <message numerus="yes">
        <source>%n timeout(s)</source>
        <translation>
            <numerusform>%n Zeitüberschreitung</numerusform>
            <numerusform>%n Zeitüberschreitungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) with a wrong BCC</source>
        <translation>
            <numerusform>%n Antwort mit falschem BCC</numerusform>
            <numerusform>%n Antworten mit falschem BCC</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n line error(s)</source>
        <translation>
            <numerusform>%n Leitungsfehler</numerusform>
            <numerusform>%n Leitungsfehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n unreadable answer(s)</source>
        <translation>
            <numerusform>%n unlesbare Antwort</numerusform>
            <numerusform>%n unlesbare Antworten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) that did not match the request</source>
        <translation>
            <numerusform>%n Antwort, die nicht zur Anfrage passte</numerusform>
            <numerusform>%n Antworten, die nicht zur Anfrage passten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n transient refusal(s) (%1)</source>
        <translation>
            <numerusform>%n vorübergehende Ablehnung (%1)</numerusform>
            <numerusform>%n vorübergehende Ablehnungen (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>timeout %1 ms</source>
        <translation>Wartezeit %1 ms</translation>
    </message>
    <message>
        <source>no answer within %1 ms (attempt %2 of %3), asking again</source>
        <translation>keine Antwort innerhalb von %1 ms (Versuch %2 von %3), neue Anfrage</translation>
    </message>
    <message>
        <source>no answer within %1 ms (attempt %2 of %3), given up</source>
        <translation>keine Antwort innerhalb von %1 ms (Versuch %2 von %3), aufgegeben</translation>
    </message>
    <message>
        <source>the drive answers again: requests are sent as before</source>
        <translation>der Umrichter antwortet wieder: Anfragen werden wie zuvor gesendet</translation>
    </message>
    <message numerus="yes">
        <source>no answer to %n request(s) in %1 s</source>
        <translation>
            <numerusform>keine Antwort auf %n Anfrage in %1 s</numerusform>
            <numerusform>keine Antwort auf %n Anfragen in %1 s</numerusform>
        </translation>
    </message>
    <message>
        <source>the drive stopped answering (%1): the requests queued fail, and one request at a time is sent once until the drive answers again</source>
        <translation>der Umrichter antwortet nicht mehr (%1): die wartenden Anfragen schlagen fehl, und bis er wieder antwortet, wird jeweils eine Anfrage einmal gesendet</translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with answers to an earlier request</source>
        <translation>
            <numerusform>%n Anfrage in Folge nur mit Antworten auf eine frühere Anfrage beantwortet</numerusform>
            <numerusform>%n Anfragen in Folge nur mit Antworten auf eine frühere Anfrage beantwortet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with frames of the wrong length</source>
        <translation>
            <numerusform>%n Anfrage in Folge nur mit Telegrammen falscher Länge beantwortet</numerusform>
            <numerusform>%n Anfragen in Folge nur mit Telegrammen falscher Länge beantwortet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with frames with a wrong checksum</source>
        <translation>
            <numerusform>%n Anfrage in Folge nur mit Telegrammen mit falscher Prüfsumme beantwortet</numerusform>
            <numerusform>%n Anfragen in Folge nur mit Telegrammen mit falscher Prüfsumme beantwortet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with answers to no request sent</source>
        <translation>
            <numerusform>%n Anfrage in Folge nur mit Antworten auf keine gesendete Anfrage beantwortet</numerusform>
            <numerusform>%n Anfragen in Folge nur mit Antworten auf keine gesendete Anfrage beantwortet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with characters the line flagged as broken</source>
        <translation>
            <numerusform>%n Anfrage in Folge nur mit Zeichen beantwortet, die die Leitung als gestört meldete</numerusform>
            <numerusform>%n Anfragen in Folge nur mit Zeichen beantwortet, die die Leitung als gestört meldete</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) in a row answered only with bytes that never made a telegram</source>
        <translation>
            <numerusform>%n Anfrage in Folge nur mit Bytes beantwortet, die nie ein Telegramm ergaben</numerusform>
            <numerusform>%n Anfragen in Folge nur mit Bytes beantwortet, die nie ein Telegramm ergaben</numerusform>
        </translation>
    </message>
    <message>
        <source>the drive has gone silent: a request was given up after every attempt and no valid answer came from the drive since</source>
        <translation>der Umrichter schweigt: eine Anfrage wurde nach allen Versuchen aufgegeben, und seitdem kam keine gültige Antwort vom Umrichter</translation>
    </message>
</context>
<context>
    <name>DriveDesk::CompareFeature</name>
    <message>
        <source>Co&amp;mpare...</source>
        <translation>&amp;Vergleichen …</translation>
    </message>
    <message>
        <source>Compare the drive, parameter files and defaults, and write chosen values</source>
        <translation>Umrichter, Parameterdateien und Vorgabewerte vergleichen und gewählte Werte schreiben</translation>
    </message>
    <message numerus="yes">
        <source>Write %n compared value(s)</source>
        <translation>
            <numerusform>%n verglichenen Wert schreiben</numerusform>
            <numerusform>%n verglichene Werte schreiben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::CompareWindow</name>
    <message>
        <source>Compare Parameters - DriveDesk</source>
        <translation>Parameter vergleichen - DriveDesk</translation>
    </message>
    <message>
        <source>Compare one &amp;set of A with one set of B</source>
        <translation>Einen &amp;Satz von A mit einem Satz von B vergleichen</translation>
    </message>
    <message>
        <source>Only the set-programmable parameters, in the sets chosen on each side. Choose &quot;A itself&quot; for B to compare two sets of one drive or file.</source>
        <translation>Nur die satzprogrammierbaren Parameter, in den auf jeder Seite gewählten Sätzen. Für B &quot;A selbst&quot; wählen, um zwei Sätze eines Umrichters oder einer Datei zu vergleichen.</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Vergleichen</translation>
    </message>
    <message>
        <source>C&amp;hoose Shown</source>
        <translation>Angezeigte &amp;wählen</translation>
    </message>
    <message>
        <source>Tick every row shown whose value can be written</source>
        <translation>Jede angezeigte Zeile ankreuzen, deren Wert geschrieben werden kann</translation>
    </message>
    <message>
        <source>C&amp;lear Choice</source>
        <translation>Auswahl &amp;löschen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Side &amp;A:</source>
        <translation>Seite &amp;A:</translation>
    </message>
    <message>
        <source>Side &amp;B:</source>
        <translation>Seite &amp;B:</translation>
    </message>
    <message>
        <source>The drive</source>
        <translation>Der Umrichter</translation>
    </message>
    <message>
        <source>The file shown in the window</source>
        <translation>Die im Fenster angezeigte Datei</translation>
    </message>
    <message>
        <source>A file</source>
        <translation>Eine Datei</translation>
    </message>
    <message>
        <source>Defaults of A</source>
        <translation>Vorgabewerte von A</translation>
    </message>
    <message>
        <source>A itself (another set)</source>
        <translation>A selbst (ein anderer Satz)</translation>
    </message>
    <message>
        <source>Parameter file (*.json)</source>
        <translation>Parameterdatei (*.json)</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen …</translation>
    </message>
    <message>
        <source>Set:</source>
        <translation>Satz:</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>Zeigen:</translation>
    </message>
    <message>
        <source>All groups</source>
        <translation>Alle Gruppen</translation>
    </message>
    <message>
        <source>&amp;Group:</source>
        <translation>&amp;Gruppe:</translation>
    </message>
    <message>
        <source>Search id, name or value</source>
        <translation>Kennung, Name oder Wert suchen</translation>
    </message>
    <message>
        <source>Sea&amp;rch:</source>
        <translation>Su&amp;chen:</translation>
    </message>
    <message>
        <source>Show only the rows ticked to be written: a last look</source>
        <translation>Nur die zum Schreiben angekreuzten Zeilen zeigen: ein letzter Blick</translation>
    </message>
    <message>
        <source>Ra&amp;w values</source>
        <translation>Ro&amp;hwerte</translation>
    </message>
    <message>
        <source>Side A: Parameter File</source>
        <translation>Seite A: Parameterdatei</translation>
    </message>
    <message>
        <source>Side B: Parameter File</source>
        <translation>Seite B: Parameterdatei</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>Side %1: no drive is connected and read.</source>
        <translation>Seite %1: kein Umrichter verbunden und gelesen.</translation>
    </message>
    <message>
        <source>the drive</source>
        <translation>der Umrichter</translation>
    </message>
    <message>
        <source>Side %1: the window shows no parameter file.</source>
        <translation>Seite %1: das Fenster zeigt keine Parameterdatei.</translation>
    </message>
    <message>
        <source>%1 (shown)</source>
        <translation>%1 (angezeigt)</translation>
    </message>
    <message>
        <source>Side %1: choose a parameter file.</source>
        <translation>Seite %1: eine Parameterdatei wählen.</translation>
    </message>
    <message>
        <source>defaults of %1</source>
        <translation>Vorgabewerte (%1)</translation>
    </message>
    <message>
        <source>%1, set %2</source>
        <translation>%1, Satz %2</translation>
    </message>
    <message numerus="yes">
        <source>Compared %1 with %2: %n value(s) differ.</source>
        <translation>
            <numerusform>Vergleich von A (%1) und B (%2): %n Wert verschieden.</numerusform>
            <numerusform>Vergleich von A (%1) und B (%2): %n Werte verschieden.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Equal (%1)</source>
        <translation>Gl&amp;eich (%1)</translation>
    </message>
    <message>
        <source>&amp;Different (%1)</source>
        <translation>Verschie&amp;den (%1)</translation>
    </message>
    <message>
        <source>Only in A (%1)</source>
        <translation>Nur in A (%1)</translation>
    </message>
    <message>
        <source>Only in B (%1)</source>
        <translation>Nur in B (%1)</translation>
    </message>
    <message>
        <source>Read-&amp;only (%1)</source>
        <translation>Schreibgeschü&amp;tzt (%1)</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n value(s) shown, %2 chosen.</source>
        <translation>
            <numerusform>%1 von %n Wert angezeigt, %2 gewählt.</numerusform>
            <numerusform>%1 von %n Werten angezeigt, %2 gewählt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Write to A</source>
        <translation>In A schreiben</translation>
    </message>
    <message>
        <source>Write to B</source>
        <translation>In B schreiben</translation>
    </message>
    <message numerus="yes">
        <source>Write %n Value(s) to A (%1)</source>
        <translation>
            <numerusform>%n Wert in A schreiben (%1)</numerusform>
            <numerusform>%n Werte in A schreiben (%1)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write %n Value(s) to B (%1)</source>
        <translation>
            <numerusform>%n Wert in B schreiben (%1)</numerusform>
            <numerusform>%n Werte in B schreiben (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>Compare Parameters</source>
        <translation>Parameter vergleichen</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) were not written:</source>
        <translation>
            <numerusform>%n Wert wurde nicht geschrieben:</numerusform>
            <numerusform>%n Werte wurden nicht geschrieben:</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing written: no drive is connected that takes a download.</source>
        <translation>Nichts geschrieben: kein Umrichter verbunden, der einen Download annimmt.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) handed to the window&apos;s download to the drive; it shows what it writes before it does.</source>
        <translation>
            <numerusform>%n Wert an den Download des Fensters zum Umrichter übergeben; er zeigt, was er schreibt, bevor er es tut.</numerusform>
            <numerusform>%n Werte an den Download des Fensters zum Umrichter übergeben; er zeigt, was er schreibt, bevor er es tut.</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing written: the window no longer shows %1.</source>
        <translation>Nichts geschrieben: das Fenster zeigt %1 nicht mehr.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) changed in %1 as one undoable edit of the window; save the file there to keep them.</source>
        <translation>
            <numerusform>%n Wert in %1 als ein rückgängig machbarer Schritt des Fensters geändert; die Datei dort speichern, um ihn zu behalten.</numerusform>
            <numerusform>%n Werte in %1 als ein rückgängig machbarer Schritt des Fensters geändert; die Datei dort speichern, um sie zu behalten.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not save %1: %2. The file on disk is as it was.</source>
        <translation>%1 konnte nicht gespeichert werden: %2. Die Datei auf dem Datenträger ist unverändert.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) written into %1.</source>
        <translation>
            <numerusform>%n Wert in %1 geschrieben.</numerusform>
            <numerusform>%n Werte in %1 geschrieben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Live and read-only values and parameters a parameter list leaves out: never counted as a difference</source>
        <translation>Istwerte, schreibgeschützte Werte und Parameter, die eine Parameterliste auslässt: zählen nie als Unterschied</translation>
    </message>
    <message>
        <source>&amp;Not settings (%1)</source>
        <translation>&amp;Keine Einstellungen (%1)</translation>
    </message>
    <message>
        <source>Chosen onl&amp;y</source>
        <translation>N&amp;ur gewählte</translation>
    </message>
    <message>
        <source>Side %1: could not read the file: %2</source>
        <translation>Seite %1: die Datei konnte nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>Nothing written: could not read the file: %1</source>
        <translation>Nichts geschrieben: die Datei konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>A drive read for this comparison is not written to here: open the drive in the editor to change it.</source>
        <translation>Ein für diesen Vergleich gelesener Umrichter wird hier nicht beschrieben: öffnen Sie den Umrichter im Editor, um ihn zu ändern.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ComparisonModel</name>
    <message>
        <source>%1 - %2</source>
        <translation>%1 - %2</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>read-only, different</source>
        <translation>schreibgeschützt, verschieden</translation>
    </message>
    <message>
        <source>read-only, equal</source>
        <translation>schreibgeschützt, gleich</translation>
    </message>
    <message>
        <source>The parameter holds one value for every set.</source>
        <translation>Der Parameter hat einen Wert für alle Sätze.</translation>
    </message>
    <message>
        <source>A download does not write this parameter: neither side can be changed to the other&apos;s value here.</source>
        <translation>Ein Download schreibt diesen Parameter nicht: keine Seite kann hier auf den Wert der anderen geändert werden.</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Satz</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>not a setting, only in A</source>
        <translation>keine Einstellung, nur in A</translation>
    </message>
    <message>
        <source>not a setting, only in B</source>
        <translation>keine Einstellung, nur in B</translation>
    </message>
    <message>
        <source>not a setting, different</source>
        <translation>keine Einstellung, verschieden</translation>
    </message>
    <message>
        <source>not a setting, equal</source>
        <translation>keine Einstellung, gleich</translation>
    </message>
    <message>
        <source>A live or read-only value, or one a parameter list leaves out: shown, never counted as a difference.</source>
        <translation>Ein Istwert, ein schreibgeschützter Wert oder einer, den eine Parameterliste auslässt: angezeigt, aber nie als Unterschied gezählt.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ConnectionDialog</name>
    <message>
        <source>Connect to a drive</source>
        <translation>Mit einem Umrichter verbinden</translation>
    </message>
    <message>
        <source>&amp;Recent connections</source>
        <translation>&amp;Letzte Verbindungen</translation>
    </message>
    <message>
        <source>&amp;Serial port</source>
        <translation>&amp;Serielle Schnittstelle</translation>
    </message>
    <message>
        <source>&amp;TCP</source>
        <translation>&amp;TCP</translation>
    </message>
    <message>
        <source>Si&amp;mulated drive</source>
        <translation>Si&amp;mulierter Umrichter</translation>
    </message>
    <message>
        <source>HSP5</source>
        <translation>HSP5</translation>
    </message>
    <message>
        <source>DIN66019II</source>
        <translation>DIN66019II</translation>
    </message>
    <message>
        <source>DIN66019</source>
        <translation>DIN66019</translation>
    </message>
    <message>
        <source>The drive&apos;s address on a DIN66019(II) bus, 0..239</source>
        <translation>Die Adresse des Umrichters an einem DIN66019(II)-Bus, 0..239</translation>
    </message>
    <message>
        <source>&amp;Find drives...</source>
        <translation>Umrichter s&amp;uchen …</translation>
    </message>
    <message>
        <source>Ask every address 0..239 on the bus which drives answer</source>
        <translation>Jede Adresse 0..239 am Bus abfragen, welche Umrichter antworten</translation>
    </message>
    <message>
        <source>Drive &amp;address:</source>
        <translation>Umrichter&amp;adresse:</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>The serial port, or type a device such as /dev/ttyUSB0 or COM3</source>
        <translation>Die serielle Schnittstelle, oder ein Gerät wie /dev/ttyUSB0 oder COM3 eingeben</translation>
    </message>
    <message>
        <source>R&amp;efresh</source>
        <translation>A&amp;ktualisieren</translation>
    </message>
    <message>
        <source>Look for serial ports again</source>
        <translation>Erneut nach seriellen Schnittstellen suchen</translation>
    </message>
    <message>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baudrate:</translation>
    </message>
    <message>
        <source>host name or IP address of the serial device server</source>
        <translation>Hostname oder IP-Adresse des seriellen Geräteservers</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>Po&amp;rt:</source>
        <translation>Po&amp;rt:</translation>
    </message>
    <message>
        <source>A simulated KEB COMBIVERT F5 running inside DriveDesk: every parameter, password levels, eight sets and a motor to watch. Nothing needs to be plugged in.</source>
        <translation>Ein simulierter KEB COMBIVERT F5, der in DriveDesk läuft: alle Parameter, Passwortebenen, acht Parametersätze und ein Motor zum Beobachten. Es muss nichts angeschlossen werden.</translation>
    </message>
    <message>
        <source>no serial port found</source>
        <translation>keine serielle Schnittstelle gefunden</translation>
    </message>
    <message>
        <source>(none yet)</source>
        <translation>(noch keine)</translation>
    </message>
    <message>
        <source>No serial port was found. Plug in the adapter and press Refresh, or type the device (e.g. /dev/ttyUSB0 or COM3).</source>
        <translation>Es wurde keine serielle Schnittstelle gefunden. Adapter einstecken und Aktualisieren drücken, oder das Gerät eingeben (z. B. /dev/ttyUSB0 oder COM3).</translation>
    </message>
    <message>
        <source>Choose the serial port the drive is connected to.</source>
        <translation>Die serielle Schnittstelle wählen, an der der Umrichter angeschlossen ist.</translation>
    </message>
    <message>
        <source>Enter the host name or IP address of the serial device server.</source>
        <translation>Hostnamen oder IP-Adresse des seriellen Geräteservers eingeben.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a host name or IP address.</source>
        <translation>„%1“ ist kein Hostname und keine IP-Adresse.</translation>
    </message>
    <message>
        <source>Finding drives needs a DIN66019II or DIN66019 bus: HSP5 is point to point. Choose the protocol first.</source>
        <translation>Die Umrichtersuche braucht einen DIN66019II- oder DIN66019-Bus: HSP5 ist eine Punkt-zu-Punkt-Verbindung. Zuerst das Protokoll wählen.</translation>
    </message>
    <message>
        <source>The drive has DriveDesk&apos;s HSP5 e&amp;xtensions</source>
        <translation>Der Umrichter kennt die HSP5-&amp;Erweiterungen von DriveDesk</translation>
    </message>
    <message>
        <source>Services 13, 14, 19-21 and 51-53, which the HSP5 specification does not define. Only for a drive known to have them: a drive without them cannot tell where such a request ends and loses the requests that follow it.</source>
        <translation>Die Dienste 13, 14, 19-21 und 51-53, die die HSP5-Spezifikation nicht festlegt. Nur für einen Umrichter, der sie sicher kennt: ein Umrichter ohne sie erkennt nicht, wo eine solche Anfrage endet, und verliert die folgenden Anfragen.</translation>
    </message>
    <message>
        <source>Automatic tries 38400, 19200, 9600, 57600 and 115200 Bd and takes the rate the drive answers at</source>
        <translation>Automatisch probiert 38400, 19200, 9600, 57600 und 115200 Bd und nimmt die Baudrate, bei der der Umrichter antwortet</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a baud rate: enter a number such as 38400, or choose Automatic.</source>
        <translation>„%1“ ist keine Baudrate: eine Zahl wie 38400 eingeben oder Automatisch wählen.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DocumentEditor</name>
    <message>
        <source>the file has no parameter %1</source>
        <translation>die Datei hat keinen Parameter %1</translation>
    </message>
    <message>
        <source>Change %1 to %2%3</source>
        <translation>%1 auf %2%3 ändern</translation>
    </message>
    <message>
        <source>%1 = %2 in the file%3; save to keep it</source>
        <translation>%1 = %2%3 in der Datei; speichern, um es zu behalten</translation>
    </message>
    <message>
        <source>Not reset: the file has no parameter %1</source>
        <translation>Nicht zurückgesetzt: die Datei hat keinen Parameter %1</translation>
    </message>
    <message>
        <source>Reset %1 to its default%2</source>
        <translation>%1%2 auf den Vorgabewert zurücksetzen</translation>
    </message>
    <message>
        <source>%1 holds its default already%2</source>
        <translation>%1 hat bereits den Vorgabewert%2</translation>
    </message>
    <message>
        <source>%1 reset to its default in the file%2</source>
        <translation>%1%2 in der Datei auf den Vorgabewert zurückgesetzt</translation>
    </message>
    <message>
        <source>Copy set %1 to set %2</source>
        <translation>Satz %1 in Satz %2 kopieren</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) read-only or locked</source>
        <translation>
            <numerusform>%n Wert schreibgeschützt oder gesperrt</numerusform>
            <numerusform>%n Werte schreibgeschützt oder gesperrt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) of set %1 not known</source>
        <translation>
            <numerusform>%n Wert von Satz %1 unbekannt</numerusform>
            <numerusform>%n Werte von Satz %1 unbekannt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) outside the limits</source>
        <translation>
            <numerusform>%n Wert außerhalb der Grenzen</numerusform>
            <numerusform>%n Werte außerhalb der Grenzen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Copied %n value(s) from set %1 to set %2 in the file</source>
        <translation>
            <numerusform>%n Wert von Satz %1 in Satz %2 der Datei kopiert</numerusform>
            <numerusform>%n Werte von Satz %1 in Satz %2 der Datei kopiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Set %1 and set %2 hold the same values: nothing to copy</source>
        <translation>Satz %1 und Satz %2 haben dieselben Werte: nichts zu kopieren</translation>
    </message>
    <message>
        <source>; left as they are: %1</source>
        <translation>; unverändert gelassen: %1</translation>
    </message>
    <message>
        <source>Undone in the file: %1</source>
        <translation>In der Datei rückgängig gemacht: %1</translation>
    </message>
    <message>
        <source>Redone in the file: %1</source>
        <translation>In der Datei wiederhergestellt: %1</translation>
    </message>
    <message>
        <source>%1; the file is unchanged</source>
        <translation>%1; die Datei ist unverändert</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DownloadDialog</name>
    <message>
        <source>Download to the Drive</source>
        <translation>In den Umrichter laden</translation>
    </message>
    <message>
        <source>Sets to write:</source>
        <translation>Zu schreibende Sätze:</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Sets</source>
        <translation>Sätze</translation>
    </message>
    <message>
        <source>Drive now</source>
        <translation>Umrichter jetzt</translation>
    </message>
    <message>
        <source>To write</source>
        <translation>Zu schreiben</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s values to compare them with the file...</source>
        <translation>Die Werte des Umrichters werden gelesen, um sie mit der Datei zu vergleichen …</translation>
    </message>
    <message>
        <source>Writing to the drive: %1</source>
        <translation>Schreiben in den Umrichter: %1</translation>
    </message>
    <message>
        <source>always written</source>
        <translation>wird immer geschrieben</translation>
    </message>
    <message>
        <source>left: %1</source>
        <translation>ausgelassen: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;The file does not fit the drive:&lt;/b&gt;&lt;ul&gt;%1&lt;/ul&gt;</source>
        <translation>&lt;b&gt;Die Datei passt nicht zum Umrichter:&lt;/b&gt;&lt;ul&gt;%1&lt;/ul&gt;</translation>
    </message>
    <message>
        <source>Nothing will be written unless you overrule the checks.</source>
        <translation>Es wird nichts geschrieben, solange Sie die Prüfungen nicht übergehen.</translation>
    </message>
    <message>
        <source>Look at what will be written, then write it.</source>
        <translation>Prüfen Sie, was geschrieben wird, und schreiben Sie es dann.</translation>
    </message>
    <message>
        <source>The drive holds the file&apos;s values already.</source>
        <translation>Der Umrichter hat die Werte der Datei bereits.</translation>
    </message>
    <message numerus="yes">
        <source>&amp;Write %n Value(s)</source>
        <translation>
            <numerusform>%n Wert &amp;schreiben</numerusform>
            <numerusform>%n Werte &amp;schreiben</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Anhalten</translation>
    </message>
    <message>
        <source>Writing to the drive...</source>
        <translation>Schreiben in den Umrichter …</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Schließen</translation>
    </message>
    <message>
        <source>Download finished: everything to write was written and read back.</source>
        <translation>Download beendet: alles Nötige wurde geschrieben und zurückgelesen.</translation>
    </message>
    <message>
        <source>The download did not write everything. The report says what the drive holds.</source>
        <translation>Der Download hat nicht alles geschrieben. Der Bericht sagt, was der Umrichter enthält.</translation>
    </message>
    <message>
        <source>Stopping after the value on its way...</source>
        <translation>Anhalten nach dem Wert, der gerade unterwegs ist …</translation>
    </message>
    <message>
        <source>Writes %1 to the drive, each read back.</source>
        <translation>Schreibt %1 in den Umrichter und liest jeden zurück.</translation>
    </message>
    <message>
        <source>Write all the same (the checks above are &amp;overruled)</source>
        <translation>Trotzdem schreiben (die Prüfungen oben werden &amp;übergangen)</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DownloadFeature</name>
    <message>
        <source>Write a parameter file&apos;s values to the drive, after a last look at what differs</source>
        <translation>Die Werte einer Parameterdatei in den Umrichter schreiben, nach einem letzten Blick auf die Unterschiede</translation>
    </message>
    <message>
        <source>Download File to Drive</source>
        <translation>Datei in den Umrichter laden</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>Es wurde nichts geschrieben: %1</translation>
    </message>
    <message>
        <source>A download is on its way already.</source>
        <translation>Ein Download läuft bereits.</translation>
    </message>
    <message>
        <source>Nothing was written: no drive is connected.</source>
        <translation>Es wurde nichts geschrieben: kein Umrichter verbunden.</translation>
    </message>
    <message>
        <source>Download finished; the values are read again.</source>
        <translation>Download beendet; die Werte werden neu gelesen.</translation>
    </message>
    <message>
        <source>the values chosen in the compare window</source>
        <translation>die im Vergleichsfenster gewählten Werte</translation>
    </message>
    <message>
        <source>Down&amp;load File to Drive...</source>
        <translation>Datei in Umrichter la&amp;den …</translation>
    </message>
    <message>
        <source>the values of %1</source>
        <translation>die Werte von %1</translation>
    </message>
    <message>
        <source>download of %1</source>
        <translation>Download: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DownloadRun</name>
    <message>
        <source>writing %1 of %2</source>
        <translation>schreibe %1 von %2</translation>
    </message>
    <message>
        <source>no drive is connected; nothing was written</source>
        <translation>kein Umrichter verbunden; es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>stopped before anything was written</source>
        <translation>angehalten, bevor etwas geschrieben wurde</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>the drive could not be read (%1); nothing was written</source>
        <translation>der Umrichter konnte nicht gelesen werden (%1); es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>the drive is no longer connected; nothing was written</source>
        <translation>der Umrichter ist nicht mehr verbunden; es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>stopped by the user</source>
        <translation>vom Benutzer abgebrochen</translation>
    </message>
    <message>
        <source>the journal cannot record the download: %1; nothing was written</source>
        <translation>das Journal kann den Download nicht festhalten: %1; es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>%1 is not described</source>
        <translation>%1 ist nicht beschrieben</translation>
    </message>
    <message>
        <source>the download ended first</source>
        <translation>der Download endete vorher</translation>
    </message>
    <message>
        <source>the journal cannot record the download: %1</source>
        <translation>das Journal kann den Download nicht festhalten: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveInfoDialog</name>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>Drive address</source>
        <translation>Umrichteradresse</translation>
    </message>
    <message>
        <source>Parameter groups</source>
        <translation>Parametergruppen</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Scan incomplete</source>
        <translation>Einlesen unvollständig</translation>
    </message>
    <message>
        <source>Drive information</source>
        <translation>Umrichterinformationen</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>Metadata</source>
        <translation>Metadaten</translation>
    </message>
    <message>
        <source>from the metadata cache of this kind of drive</source>
        <translation>aus dem Metadaten-Cache dieser Umrichterart</translation>
    </message>
    <message>
        <source>read from the drive</source>
        <translation>vom Umrichter gelesen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveScanner</name>
    <message>
        <source>identification</source>
        <translation>Identifikation</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>group page %1h</source>
        <translation>Gruppenseite %1h</translation>
    </message>
    <message>
        <source>group page %1h: %2</source>
        <translation>Gruppenseite %1h: %2</translation>
    </message>
    <message>
        <source>group %1: name</source>
        <translation>Gruppe %1: Name</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>limits</source>
        <translation>Grenzwerte</translation>
    </message>
    <message>
        <source>default value</source>
        <translation>Vorgabewert</translation>
    </message>
    <message>
        <source>properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>values: not read, the properties are unknown</source>
        <translation>Werte: nicht gelesen, die Eigenschaften sind unbekannt</translation>
    </message>
    <message>
        <source>display scaling</source>
        <translation>Anzeigenormierung</translation>
    </message>
    <message>
        <source>plaintext indices</source>
        <translation>Klartextindizes</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>value of set %1</source>
        <translation>Wert in Satz %1</translation>
    </message>
    <message>
        <source>plaintexts: the drive names %1 definitions, only %2 can be read</source>
        <translation>Klartexte: der Umrichter nennt %1 Definitionen, nur %2 können gelesen werden</translation>
    </message>
    <message>
        <source>plaintext definition %1</source>
        <translation>Klartextdefinition %1</translation>
    </message>
    <message>
        <source>plaintext %1.%2</source>
        <translation>Klartext %1.%2</translation>
    </message>
    <message>
        <source>group %1: parameter %2</source>
        <translation>Gruppe %1: Parameter %2</translation>
    </message>
    <message>
        <source>the answer carries no %1</source>
        <translation>die Antwort enthält keine Daten für „%1“</translation>
    </message>
    <message numerus="yes">
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (und %n weiteres)</numerusform>
            <numerusform>%1 (und %n weitere)</numerusform>
        </translation>
    </message>
    <message>
        <source>identification %1h</source>
        <translation>Kennung %1h</translation>
    </message>
    <message>
        <source>values of sets %1</source>
        <translation>Werte der Sätze %1</translation>
    </message>
    <message>
        <source>%1: not confirmed when read again on a line with errors</source>
        <translation>%1: auf einer Leitung mit Fehlern beim erneuten Lesen nicht bestätigt</translation>
    </message>
    <message>
        <source>the answers did not agree</source>
        <translation>die Antworten stimmten nicht überein</translation>
    </message>
    <message>
        <source>implausible answer: %1</source>
        <translation>unplausible Antwort: %1</translation>
    </message>
    <message>
        <source>default value: %1</source>
        <translation>Vorgabewert: %1</translation>
    </message>
    <message>
        <source>value of set %1: %2</source>
        <translation>Wert von Satz %1: %2</translation>
    </message>
    <message>
        <source>group %1: %2 of %3 parameters found</source>
        <translation>Gruppe %1: %2 von %3 Parametern gefunden</translation>
    </message>
    <message>
        <source>group %1: %2 of %3 parameters found; no answer for %4 (%5)</source>
        <translation>Gruppe %1: %2 von %3 Parametern gefunden; keine Antwort für %4 (%5)</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) without a valid answer (%1)</source>
        <translation>
            <numerusform>%n Parameter ohne gültige Antwort (%1)</numerusform>
            <numerusform>%n Parameter ohne gültige Antwort (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: not confirmed: the drive changes it by itself, and on a line with errors no two reads agreed</source>
        <translation>%1: nicht bestätigt: der Umrichter ändert den Wert selbst, und auf einer Leitung mit Fehlern stimmten keine zwei Lesungen überein</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveSession</name>
    <message>
        <source>the scan was cancelled</source>
        <translation>das Einlesen wurde abgebrochen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::DriveState</name>
    <message>
        <source>there is no parameter %1</source>
        <translation>es gibt keinen Parameter %1</translation>
    </message>
    <message>
        <source>the drive holds %1, not %2</source>
        <translation>der Umrichter enthält %1, nicht %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::EditController</name>
    <message>
        <source>Not written: this drive has no parameter %1</source>
        <translation>Nicht geschrieben: dieser Umrichter hat keinen Parameter %1</translation>
    </message>
    <message>
        <source>%1 not written: no set chosen</source>
        <translation>%1 nicht geschrieben: kein Satz gewählt</translation>
    </message>
    <message>
        <source>Not reset: this drive has no parameter %1</source>
        <translation>Nicht zurückgesetzt: dieser Umrichter hat keinen Parameter %1</translation>
    </message>
    <message>
        <source>%1 not reset: no set chosen</source>
        <translation>%1 nicht zurückgesetzt: kein Satz gewählt</translation>
    </message>
    <message>
        <source>Reset %1 to its default%2</source>
        <translation>%1%2 auf den Vorgabewert zurücksetzen</translation>
    </message>
    <message>
        <source>Write %1 = %2%3</source>
        <translation>%1 = %2%3 schreiben</translation>
    </message>
    <message>
        <source>%1%2: the value before the change is not known, so it stays as it is</source>
        <translation>%1%2: der Wert vor der Änderung ist unbekannt, er bleibt daher, wie er ist</translation>
    </message>
    <message>
        <source>Undone: %1</source>
        <translation>Rückgängig gemacht: %1</translation>
    </message>
    <message>
        <source>Redone: %1</source>
        <translation>Wiederhergestellt: %1</translation>
    </message>
    <message>
        <source>Undo failed: %1: %2</source>
        <translation>Rückgängigmachen fehlgeschlagen: %1: %2</translation>
    </message>
    <message>
        <source>Redo failed: %1: %2</source>
        <translation>Wiederherstellen fehlgeschlagen: %1: %2</translation>
    </message>
    <message>
        <source>Still copying set %1 to set %2</source>
        <translation>Satz %1 wird noch in Satz %2 kopiert</translation>
    </message>
    <message>
        <source>Still reading the values</source>
        <translation>Die Werte werden noch gelesen</translation>
    </message>
    <message>
        <source>Cannot copy set %1 to set %2: the sets are 0 to %3</source>
        <translation>Satz %1 kann nicht in Satz %2 kopiert werden: die Sätze sind 0 bis %3</translation>
    </message>
    <message>
        <source>Cannot copy set %1 onto itself</source>
        <translation>Satz %1 kann nicht in sich selbst kopiert werden</translation>
    </message>
    <message>
        <source>Copy set %1 to set %2</source>
        <translation>Satz %1 in Satz %2 kopieren</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Set %2 holds the values of set %1 already</source>
        <translation>Satz %2 enthält bereits die Werte von Satz %1</translation>
    </message>
    <message numerus="yes">
        <source>Set %1 copied to set %2: %n value(s) written</source>
        <translation>
            <numerusform>Satz %1 in Satz %2 kopiert: %n Wert geschrieben</numerusform>
            <numerusform>Satz %1 in Satz %2 kopiert: %n Werte geschrieben</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n refused (%1)</source>
        <translation>
            <numerusform>%n abgelehnt (%1)</numerusform>
            <numerusform>%n abgelehnt (%1)</numerusform>
        </translation>
    </message>
    <message>
        <source>stopped: %1</source>
        <translation>angehalten: %1</translation>
    </message>
    <message numerus="yes">
        <source>cancelled, %n value(s) not copied</source>
        <translation>
            <numerusform>abgebrochen, %n Wert nicht kopiert</numerusform>
            <numerusform>abgebrochen, %n Werte nicht kopiert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) left as they are: read-only or above the password level</source>
        <translation>
            <numerusform>%n Parameter unverändert gelassen: schreibgeschützt oder über der Passwortebene</numerusform>
            <numerusform>%n Parameter unverändert gelassen: schreibgeschützt oder über der Passwortebene</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) left out: the value in set %1 was never read</source>
        <translation>
            <numerusform>%n Parameter ausgelassen: der Wert in Satz %1 wurde nie gelesen</numerusform>
            <numerusform>%n Parameter ausgelassen: der Wert in Satz %1 wurde nie gelesen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) read</source>
        <translation>
            <numerusform>%n Wert gelesen</numerusform>
            <numerusform>%n Werte gelesen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n could not be read (first: %1%2: %3)</source>
        <translation>
            <numerusform>%n konnte nicht gelesen werden (erster: %1%2: %3)</numerusform>
            <numerusform>%n konnten nicht gelesen werden (erster: %1%2: %3)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>cancelled, %n value(s) not read</source>
        <translation>
            <numerusform>abgebrochen, %n Wert nicht gelesen</numerusform>
            <numerusform>abgebrochen, %n Werte nicht gelesen</numerusform>
        </translation>
    </message>
    <message>
        <source>; the drive changes this value itself, so the write cannot be undone</source>
        <translation>; der Umrichter ändert diesen Wert selbst, daher kann das Schreiben nicht rückgängig gemacht werden</translation>
    </message>
    <message>
        <source>this drive has no parameter %1</source>
        <translation>dieser Umrichter hat keinen Parameter %1</translation>
    </message>
    <message>
        <source>Set %1 not copied to set %2: %3</source>
        <translation>Satz %1 nicht in Satz %2 kopiert: %3</translation>
    </message>
    <message>
        <source>the copy was cancelled</source>
        <translation>das Kopieren wurde abgebrochen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::EditingFeature</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>Undo %1</source>
        <translation>Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederherstellen: %1</translation>
    </message>
    <message>
        <source>Redo %1</source>
        <translation>Wiederherstellen: %1</translation>
    </message>
    <message>
        <source>Reset to &amp;Default</source>
        <translation>Auf &amp;Vorgabewert zurücksetzen</translation>
    </message>
    <message>
        <source>Set the selected values to the drive&apos;s default</source>
        <translation>Die gewählten Werte auf den Vorgabewert des Umrichters setzen</translation>
    </message>
    <message>
        <source>&amp;Write to Sets...</source>
        <translation>&amp;In Sätze schreiben …</translation>
    </message>
    <message>
        <source>Write a value to several parameter sets at once</source>
        <translation>Einen Wert in mehrere Parametersätze zugleich schreiben</translation>
    </message>
    <message>
        <source>&amp;Copy Set...</source>
        <translation>Satz &amp;kopieren …</translation>
    </message>
    <message>
        <source>Copy every set-programmable value from one set to another</source>
        <translation>Alle satzprogrammierbaren Werte von einem Satz in einen anderen kopieren</translation>
    </message>
    <message numerus="yes">
        <source>Not reset, read-only or above the password level in force: %1 and %n more</source>
        <translation>
            <numerusform>Nicht zurückgesetzt, schreibgeschützt oder über der gültigen Passwortebene: %1 und %n weiterer</numerusform>
            <numerusform>Nicht zurückgesetzt, schreibgeschützt oder über der gültigen Passwortebene: %1 und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>Not reset, read-only or above the password level in force: %1</source>
        <translation>Nicht zurückgesetzt, schreibgeschützt oder über der gültigen Passwortebene: %1</translation>
    </message>
    <message>
        <source>%1 is not set-programmable: it holds one value for every set.</source>
        <translation>%1 ist nicht satzprogrammierbar: er hat einen Wert für alle Sätze.</translation>
    </message>
    <message>
        <source>%1 has no value read in set %2 to write.</source>
        <translation>Für %1 ist in Satz %2 kein gelesener Wert zum Schreiben vorhanden.</translation>
    </message>
    <message>
        <source>Write to Sets</source>
        <translation>In Sätze schreiben</translation>
    </message>
    <message>
        <source>Write %1 to %2 in:</source>
        <translation>%1 in %2 schreiben, in:</translation>
    </message>
    <message>
        <source>Copy Set</source>
        <translation>Satz kopieren</translation>
    </message>
    <message>
        <source>Copy every set-programmable value you may change from one set to another:</source>
        <translation>Alle satzprogrammierbaren Werte, die Sie ändern dürfen, von einem Satz in einen anderen kopieren:</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ExportFeature</name>
    <message>
        <source>Export as &amp;CSV...</source>
        <translation>Als &amp;CSV exportieren …</translation>
    </message>
    <message>
        <source>Write every parameter with its unit and each set&apos;s value as shown to a CSV file for a spreadsheet</source>
        <translation>Jeden Parameter mit Einheit und dem angezeigten Wert jedes Satzes in eine CSV-Datei für eine Tabellenkalkulation schreiben</translation>
    </message>
    <message>
        <source>Export as CSV</source>
        <translation>Als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Not exported: %1. The file on disk is as it was.</source>
        <translation>Nicht exportiert: %1. Die Datei auf dem Datenträger ist unverändert.</translation>
    </message>
    <message numerus="yes">
        <source>Exported %n parameter(s) to %1.</source>
        <translation>
            <numerusform>%n Parameter nach %1 exportiert.</numerusform>
            <numerusform>%n Parameter nach %1 exportiert.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::FilterBar</name>
    <message>
        <source>Search every group by id, name or value</source>
        <translation>Alle Gruppen nach Kennung, Name oder Wert durchsuchen</translation>
    </message>
    <message>
        <source>&amp;Find...</source>
        <translation>&amp;Suchen …</translation>
    </message>
    <message>
        <source>Search parameters by id, name or value</source>
        <translation>Parameter nach Kennung, Name oder Wert suchen</translation>
    </message>
    <message>
        <source>Search every group by id (ru.3), name or value as you type (%1)</source>
        <translation>Alle Gruppen während der Eingabe nach Kennung (ru.3), Name oder Wert durchsuchen (%1)</translation>
    </message>
    <message>
        <source>&amp;Differs from Default</source>
        <translation>&amp;Abweichend vom Vorgabewert</translation>
    </message>
    <message>
        <source>F&amp;avourites</source>
        <translation>&amp;Favoriten</translation>
    </message>
    <message>
        <source>F&amp;avourites Only</source>
        <translation>Nur &amp;Favoriten</translation>
    </message>
    <message>
        <source>Only the parameters marked with a star</source>
        <translation>Nur die mit einem Stern markierten Parameter</translation>
    </message>
    <message>
        <source>&amp;Hide Parameters above Password Level</source>
        <translation>Parameter über der Passwortebene aus&amp;blenden</translation>
    </message>
    <message>
        <source>Hide parameters the password level in force does not open; otherwise they are greyed out</source>
        <translation>Parameter ausblenden, die die gültige Passwortebene nicht freigibt; sonst werden sie ausgegraut</translation>
    </message>
    <message>
        <source>Ra&amp;w values</source>
        <translation>&amp;Rohwerte</translation>
    </message>
    <message>
        <source>Show &amp;Raw Values</source>
        <translation>&amp;Rohwerte anzeigen</translation>
    </message>
    <message>
        <source>Show the raw integers the drive holds instead of scaled values and plaintexts</source>
        <translation>Die ganzzahligen Rohwerte des Umrichters statt normierter Werte und Klartexte anzeigen</translation>
    </message>
    <message>
        <source>Only settings whose value differs from the default (not read-only or live values)</source>
        <translation>Nur Einstellungen, deren Wert vom Vorgabewert abweicht (keine schreibgeschützten oder laufend gemessenen Werte)</translation>
    </message>
    <message>
        <source>D&amp;iffers from default</source>
        <translation>Vom Vorgabewert ab&amp;weichend</translation>
    </message>
    <message>
        <source>Hide above &amp;password level</source>
        <translation>Über der &amp;Passwortebene ausblenden</translation>
    </message>
</context>
<context>
    <name>DriveDesk::FindDrivesDialog</name>
    <message>
        <source>the %1 bus on %2 at %3 baud</source>
        <translation>dem %1-Bus an %2 mit %3 Baud</translation>
    </message>
    <message>
        <source>the %1 bus behind %2</source>
        <translation>dem %1-Bus hinter %2</translation>
    </message>
    <message>
        <source>the simulated %1 bus</source>
        <translation>dem simulierten %1-Bus</translation>
    </message>
    <message>
        <source>Find drives</source>
        <translation>Umrichter suchen</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stopp</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>Search &amp;again</source>
        <translation>&amp;Erneut suchen</translation>
    </message>
    <message>
        <source>Drives that answered:</source>
        <translation>Umrichter, die geantwortet haben:</translation>
    </message>
    <message>
        <source>Asking every address %2..%3 on %1 whether a drive answers.</source>
        <translation>Alle Adressen %2..%3 auf %1 werden gefragt, ob ein Umrichter antwortet.</translation>
    </message>
    <message>
        <source>not connected to the bus</source>
        <translation>nicht mit dem Bus verbunden</translation>
    </message>
    <message>
        <source>Opening the connection...</source>
        <translation>Verbindung wird geöffnet …</translation>
    </message>
    <message>
        <source>Searching...</source>
        <translation>Suche läuft …</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Angehalten.</translation>
    </message>
    <message>
        <source>The search stopped: %1</source>
        <translation>Die Suche wurde beendet: %1</translation>
    </message>
    <message>
        <source>No drive answered. Check the wiring, the baud rate and the protocol.</source>
        <translation>Kein Umrichter hat geantwortet. Verdrahtung, Baudrate und Protokoll prüfen.</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) answered.</source>
        <translation>
            <numerusform>%n Umrichter hat geantwortet.</numerusform>
            <numerusform>%n Umrichter haben geantwortet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not search: %1</source>
        <translation>Suche nicht möglich: %1</translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation>Wird angehalten …</translation>
    </message>
    <message>
        <source>Drive %1, connected now</source>
        <translation>Umrichter %1, jetzt verbunden</translation>
    </message>
    <message>
        <source>Drive %1</source>
        <translation>Umrichter %1</translation>
    </message>
    <message>
        <source>gave no identification</source>
        <translation>keine Kennung erhalten</translation>
    </message>
    <message numerus="yes">
        <source>Stopped after %1 of %2 addresses: %n drive(s) answered.</source>
        <translation>
            <numerusform>Nach %1 von %2 Adressen angehalten: %n Umrichter hat geantwortet.</numerusform>
            <numerusform>Nach %1 von %2 Adressen angehalten: %n Umrichter haben geantwortet.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::GroupListModel</name>
    <message>
        <source>All parameters</source>
        <translation>Alle Parameter</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
</context>
<context>
    <name>DriveDesk::HexValueEdit</name>
    <message>
        <source>Hexadecimal, %1 .. %2</source>
        <translation>Hexadezimal, %1 .. %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::JournalDock</name>
    <message>
        <source>Journal</source>
        <translation>Journal</translation>
    </message>
    <message>
        <source>Drive:</source>
        <translation>Umrichter:</translation>
    </message>
    <message>
        <source>serial number, link or link@address</source>
        <translation>Seriennummer, Verbindung oder Verbindung@Adresse</translation>
    </message>
    <message>
        <source>Parameter:</source>
        <translation>Parameter:</translation>
    </message>
    <message>
        <source>op.28 or 0x0A1C</source>
        <translation>op.28 oder 0x0A1C</translation>
    </message>
    <message>
        <source>User:</source>
        <translation>Benutzer:</translation>
    </message>
    <message>
        <source>login name</source>
        <translation>Anmeldename</translation>
    </message>
    <message>
        <source>Since:</source>
        <translation>Von:</translation>
    </message>
    <message>
        <source>2026-11-24 or 2026-11-24 10:42</source>
        <translation>2026-11-24 oder 2026-11-24 10:42</translation>
    </message>
    <message>
        <source>Until:</source>
        <translation>Bis:</translation>
    </message>
    <message>
        <source>Search:</source>
        <translation>Suche:</translation>
    </message>
    <message>
        <source>any field of the entries shown</source>
        <translation>beliebiges Feld der gezeigten Einträge</translation>
    </message>
    <message>
        <source>This Drive</source>
        <translation>Dieser Umrichter</translation>
    </message>
    <message>
        <source>Show the entries of the connected drive</source>
        <translation>Die Einträge des verbundenen Umrichters zeigen</translation>
    </message>
    <message>
        <source>Load Older</source>
        <translation>Ältere laden</translation>
    </message>
    <message numerus="yes">
        <source>Read the %n entries before the oldest shown</source>
        <translation>
            <numerusform>%n Eintrag vor dem ältesten gezeigten lesen</numerusform>
            <numerusform>%n Einträge vor dem ältesten gezeigten lesen</numerusform>
        </translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Revert...</source>
        <translation>Zurücksetzen …</translation>
    </message>
    <message>
        <source>Write the values before the selected entries back to the drive, after a last look at what will change</source>
        <translation>Die Werte von vor den gewählten Einträgen zurück in den Umrichter schreiben, nach einem letzten Blick auf das, was sich ändert</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not after &apos;%2&apos;</source>
        <translation>„%1“ liegt nicht nach „%2“</translation>
    </message>
    <message>
        <source>Reading the journal...</source>
        <translation>Journal wird gelesen …</translation>
    </message>
    <message numerus="yes">
        <source>%n entries</source>
        <translation>
            <numerusform>%n Eintrag</numerusform>
            <numerusform>%n Einträge</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n entries match the search</source>
        <translation>
            <numerusform>Suchtreffer: %1 von %n Eintrag</numerusform>
            <numerusform>Suchtreffer: %1 von %n Einträgen</numerusform>
        </translation>
    </message>
    <message>
        <source>older ones not read yet</source>
        <translation>ältere noch nicht gelesen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::JournalFeature</name>
    <message>
        <source>&amp;Journal</source>
        <translation>&amp;Journal</translation>
    </message>
    <message>
        <source>The values written to drives: who, when, before and after</source>
        <translation>Die in Umrichter geschriebenen Werte: wer, wann, vorher und nachher</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Nothing was written: no drive is connected.</source>
        <translation>Es wurde nichts geschrieben: kein Umrichter verbunden.</translation>
    </message>
    <message>
        <source>Nothing was written:
%1</source>
        <translation>Es wurde nichts geschrieben:
%1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::JournalTableModel</name>
    <message>
        <source>active</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>(password)</source>
        <translation>(Passwort)</translation>
    </message>
    <message>
        <source>%1 on %2, software %3, serial number %4</source>
        <translation>%1 an %2, Software %3, Seriennummer %4</translation>
    </message>
    <message>
        <source>Answered %1</source>
        <translation>Beantwortet %1</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Rechner</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Umrichter</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Satz</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <source>Written</source>
        <translation>Geschrieben</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>Zurückgelesen</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Ergebnis</translation>
    </message>
</context>
<context>
    <name>DriveDesk::MainWindow</name>
    <message>
        <source>DriveDesk</source>
        <translation>DriveDesk</translation>
    </message>
    <message>
        <source>Not connected. Choose Connect... (%1) to reach a drive or the simulated one.</source>
        <translation>Nicht verbunden. Verbinden … (%1) wählen, um einen Umrichter oder den simulierten zu erreichen.</translation>
    </message>
    <message>
        <source>Connected. Reading the drive...</source>
        <translation>Verbunden. Umrichter wird eingelesen …</translation>
    </message>
    <message>
        <source>Reconnected to %1; reading the values again.</source>
        <translation>Wieder verbunden (%1); die Werte werden neu gelesen.</translation>
    </message>
    <message>
        <source>Reading the drive...</source>
        <translation>Umrichter wird eingelesen …</translation>
    </message>
    <message>
        <source>Connecting...</source>
        <translation>Verbindung wird aufgebaut …</translation>
    </message>
    <message>
        <source>Connecting to %1...</source>
        <translation>Verbindung wird aufgebaut: %1 …</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>Verbunden: %1</translation>
    </message>
    <message>
        <source>Connection lost</source>
        <translation>Verbindung verloren</translation>
    </message>
    <message>
        <source>Reading the drive: %1</source>
        <translation>Umrichter wird eingelesen: %1</translation>
    </message>
    <message>
        <source>%1 - DriveDesk</source>
        <translation>%1 – DriveDesk</translation>
    </message>
    <message>
        <source>The drive reported no parameters.</source>
        <translation>Der Umrichter hat keine Parameter gemeldet.</translation>
    </message>
    <message>
        <source>Nothing was read from the drive: %1.</source>
        <translation>Vom Umrichter wurde nichts gelesen: %1.</translation>
    </message>
    <message>
        <source>Nothing was read: %1. Press Refresh (%2) to read the drive.</source>
        <translation>Nichts gelesen: %1. Aktualisieren (%2) drücken, um den Umrichter einzulesen.</translation>
    </message>
    <message>
        <source>The connection to the drive was lost: %1. What was read stays shown; editing is off until the drive is reconnected.</source>
        <translation>Die Verbindung zum Umrichter ist abgebrochen: %1. Das Gelesene bleibt sichtbar; Bearbeiten ist gesperrt, bis der Umrichter wieder verbunden ist.</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Verbindung verloren: %1</translation>
    </message>
    <message>
        <source>Could not connect: %1</source>
        <translation>Verbindung nicht möglich: %1</translation>
    </message>
    <message>
        <source>Could not connect to %1: %2</source>
        <translation>Verbindung nicht möglich (%1): %2</translation>
    </message>
    <message>
        <source>Disconnected from %1. What was read stays shown.</source>
        <translation>Getrennt (%1). Das Gelesene bleibt sichtbar.</translation>
    </message>
    <message>
        <source>&amp;Connect...</source>
        <translation>&amp;Verbinden …</translation>
    </message>
    <message>
        <source>Connect to a drive or the simulated one</source>
        <translation>Mit einem Umrichter oder dem simulierten verbinden</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>&amp;Find Drives...</source>
        <translation>Umrichter &amp;suchen …</translation>
    </message>
    <message>
        <source>Look for drives at the addresses 0..239 of a DIN66019II bus</source>
        <translation>Umrichter an den Adressen 0..239 eines DIN66019II-Busses suchen</translation>
    </message>
    <message>
        <source>&amp;Refresh</source>
        <translation>&amp;Aktualisieren</translation>
    </message>
    <message>
        <source>Read every value from the drive again</source>
        <translation>Alle Werte erneut vom Umrichter lesen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;About DriveDesk</source>
        <translation>&amp;Über DriveDesk</translation>
    </message>
    <message>
        <source>&amp;Drive</source>
        <translation>&amp;Umrichter</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>DriveDesk uses the new language from its next start on: the window&apos;s texts and the drive&apos;s own texts.</source>
        <translation>DriveDesk verwendet die neue Sprache ab dem nächsten Start: für die Texte des Fensters und die eigenen Texte des Umrichters.</translation>
    </message>
    <message>
        <source>About DriveDesk</source>
        <translation>Über DriveDesk</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;DriveDesk&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Reads and edits the parameters of KEB frequency inverters over HSP5, DIN66019II and DIN66019, and ships a simulated COMBIVERT F5.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;DriveDesk&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Liest und bearbeitet die Parameter von KEB-Frequenzumrichtern über HSP5, DIN66019II und DIN66019 und bringt einen simulierten COMBIVERT F5 mit.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Read &amp;Metadata Again</source>
        <translation>&amp;Metadaten neu lesen</translation>
    </message>
    <message>
        <source>Read the groups, names, limits and texts from the drive instead of the metadata cache</source>
        <translation>Gruppen, Namen, Grenzen und Texte vom Umrichter lesen statt aus dem Metadaten-Cache</translation>
    </message>
    <message>
        <source>Metadata from cache</source>
        <translation>Metadaten aus dem Cache</translation>
    </message>
    <message>
        <source>The groups, names, limits and texts come from the metadata cache of this kind of drive; the values were read from the drive. Drive &gt; Read Metadata Again reads everything.</source>
        <translation>Gruppen, Namen, Grenzen und Texte stammen aus dem Metadaten-Cache dieser Umrichterart; die Werte wurden vom Umrichter gelesen. Umrichter &gt; Metadaten neu lesen liest alles.</translation>
    </message>
    <message numerus="yes">
        <source>Read %n parameter(s).</source>
        <translation>
            <numerusform>%n Parameter gelesen.</numerusform>
            <numerusform>%n Parameter gelesen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The drive has %n group(s).</source>
        <translation>
            <numerusform>Der Umrichter hat %n Gruppe.</numerusform>
            <numerusform>Der Umrichter hat %n Gruppen.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Language (from the next start)</source>
        <translation>S&amp;prache (ab dem nächsten Start)</translation>
    </message>
    <message>
        <source>Takes effect when DriveDesk starts again</source>
        <translation>Gilt ab dem nächsten Start von DriveDesk</translation>
    </message>
    <message>
        <source>Closing the connection to %1...</source>
        <translation>Die Verbindung zu %1 wird geschlossen …</translation>
    </message>
    <message>
        <source>Connected: %1; the drive is not answering</source>
        <translation>Verbunden: %1; der Umrichter antwortet nicht</translation>
    </message>
    <message numerus="yes">
        <source>the table shows the %n parameter(s) read</source>
        <translation>
            <numerusform>die Tabelle zeigt den %n gelesenen Parameter</numerusform>
            <numerusform>die Tabelle zeigt die %n gelesenen Parameter</numerusform>
        </translation>
    </message>
    <message>
        <source>The drive was read only in part (%1): %2. Read it again with Drive &gt; Read Metadata Again.</source>
        <translation>Der Umrichter wurde nur teilweise gelesen (%1): %2. Umrichter &gt; Metadaten neu lesen liest ihn neu.</translation>
    </message>
    <message>
        <source>Incomplete: %1</source>
        <translation>Unvollständig: %1</translation>
    </message>
    <message>
        <source>The drive is not answering</source>
        <translation>Der Umrichter antwortet nicht</translation>
    </message>
    <message>
        <source>The drive answers again.</source>
        <translation>Der Umrichter antwortet wieder.</translation>
    </message>
    <message>
        <source>Could not connect to %1: %2. What was shown before stays.</source>
        <translation>Keine Verbindung zu %1: %2. Was vorher angezeigt wurde, bleibt stehen.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n parameter(s), no drive connected.</source>
        <translation>
            <numerusform>%1 geöffnet: %n Parameter, kein Umrichter verbunden.</numerusform>
            <numerusform>%1 geöffnet: %n Parameter, kein Umrichter verbunden.</numerusform>
        </translation>
    </message>
    <message>
        <source>Disconnected from %1 to show the parameter file %2.</source>
        <translation>Verbindung zu %1 getrennt, um die Parameterdatei %2 anzuzeigen.</translation>
    </message>
    <message>
        <source>No drive: parameter file</source>
        <translation>Kein Umrichter: Parameterdatei</translation>
    </message>
    <message>
        <source>The parameter file holds no parameters.</source>
        <translation>Die Parameterdatei enthält keine Parameter.</translation>
    </message>
    <message>
        <source>%1[*] - DriveDesk</source>
        <translation>%1[*] - DriveDesk</translation>
    </message>
    <message>
        <source>Replace File</source>
        <translation>Datei ersetzen</translation>
    </message>
    <message>
        <source>%1 exists already. Replace it?</source>
        <translation>%1 gibt es bereits. Ersetzen?</translation>
    </message>
    <message>
        <source>&amp;Replace</source>
        <translation>&amp;Ersetzen</translation>
    </message>
    <message>
        <source>DriveDesk parameter files (*.json)</source>
        <translation>DriveDesk-Parameterdateien (*.json)</translation>
    </message>
    <message>
        <source>Reconnected to %1; the drive was read only in part: reading it again.</source>
        <translation>Wieder mit %1 verbunden; der Umrichter war nur teilweise gelesen: er wird erneut gelesen.</translation>
    </message>
    <message>
        <source>Reading the drive again stopped (%1). The table keeps what was read before: every parameter with its limits, units and texts, and the values as last read.</source>
        <translation>Das erneute Lesen des Umrichters wurde beendet (%1). Die Tabelle behält, was vorher gelesen wurde: jeden Parameter mit Grenzwerten, Einheiten und Texten und die zuletzt gelesenen Werte.</translation>
    </message>
    <message>
        <source>Reading the drive again stopped: %1</source>
        <translation>Das erneute Lesen des Umrichters wurde beendet: %1</translation>
    </message>
    <message>
        <source>Drive Inf&amp;ormation...</source>
        <translation>Umrichter-Inf&amp;ormationen …</translation>
    </message>
    <message>
        <source>The drive is not answering: the connection to %1 is open, but no valid answer came from the drive since %2 (nothing at all, or only what cannot be an answer). The values shown are the last read and are marked stale. This clears by itself when the drive answers again.</source>
        <translation>Der Umrichter antwortet nicht: die Verbindung zu %1 ist offen, aber seit %2 kam keine gültige Antwort vom Umrichter (gar nichts, oder nur, was keine Antwort sein kann). Die angezeigten Werte sind die zuletzt gelesenen und als veraltet markiert. Das verschwindet von selbst, sobald der Umrichter wieder antwortet.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::MonitorFeature</name>
    <message>
        <source>&amp;Telegram Monitor</source>
        <translation>&amp;Telegramm-Monitor</translation>
    </message>
</context>
<context>
    <name>DriveDesk::NoticeBar</name>
    <message>
        <source>&amp;Cancel</source>
        <translation>Abbre&amp;chen</translation>
    </message>
    <message>
        <source>&amp;Reconnect</source>
        <translation>&amp;Neu verbinden</translation>
    </message>
    <message>
        <source>C&amp;onnect...</source>
        <translation>V&amp;erbinden …</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterBrowser</name>
    <message>
        <source>Search results for “%1”</source>
        <translation>Suchergebnisse für „%1“</translation>
    </message>
    <message>
        <source>All parameters</source>
        <translation>Alle Parameter</translation>
    </message>
    <message>
        <source>Not connected. Connect to a drive to see its parameters.</source>
        <translation>Nicht verbunden. Mit einem Umrichter verbinden, um seine Parameter zu sehen.</translation>
    </message>
    <message>
        <source>No parameter here matches the search and the filters.</source>
        <translation>Kein Parameter hier passt zur Suche und zu den Filtern.</translation>
    </message>
    <message>
        <source>This group holds no parameters.</source>
        <translation>Diese Gruppe enthält keine Parameter.</translation>
    </message>
    <message>
        <source>Favourite</source>
        <translation>Favorit</translation>
    </message>
    <message>
        <source>%1: none shown</source>
        <translation>%1: keiner angezeigt</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n parameter(s) (filtered)</source>
        <translation>
            <numerusform>%1: %n Parameter (gefiltert)</numerusform>
            <numerusform>%1: %n Parameter (gefiltert)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n parameter(s)</source>
        <translation>
            <numerusform>%1: %n Parameter</numerusform>
            <numerusform>%1: %n Parameter</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterDelegate</name>
    <message>
        <source>this parameter cannot be changed now</source>
        <translation>dieser Parameter kann jetzt nicht geändert werden</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <comment>parameter, set</comment>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterFileFeature</name>
    <message>
        <source>&amp;Open Parameter File...</source>
        <translation>Parameterdatei ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Show and edit a parameter file with no drive</source>
        <translation>Eine Parameterdatei ohne Umrichter anzeigen und bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the changes of the parameter file shown</source>
        <translation>Die Änderungen der angezeigten Parameterdatei speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>Save the parameter file shown under another name</source>
        <translation>Die angezeigte Parameterdatei unter einem anderen Namen speichern</translation>
    </message>
    <message>
        <source>Open Parameter File</source>
        <translation>Parameterdatei öffnen</translation>
    </message>
    <message>
        <source>Could not open the file: %1</source>
        <translation>Die Datei konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>No drive is connected: the table shows the parameter file %1, and edits change the file only, once you save it (%2). Nothing is sent to a drive.</source>
        <translation>Kein Umrichter verbunden: die Tabelle zeigt die Parameterdatei %1, und Änderungen ändern nur die Datei, sobald Sie sie speichern (%2). Nichts wird an einen Umrichter gesendet.</translation>
    </message>
    <message>
        <source>Save Parameter File</source>
        <translation>Parameterdatei speichern</translation>
    </message>
    <message>
        <source>Could not save %1: %2. The file on disk is as it was.</source>
        <translation>%1 konnte nicht gespeichert werden: %2. Die Datei auf dem Datenträger ist unverändert.</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 gespeichert.</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The parameter file %1 has changes that are not saved.</source>
        <translation>Die Parameterdatei %1 hat Änderungen, die nicht gespeichert sind.</translation>
    </message>
    <message>
        <source>Save them before going on?</source>
        <translation>Vor dem Fortfahren speichern?</translation>
    </message>
    <message>
        <source>Save Parameter File As</source>
        <translation>Parameterdatei speichern unter</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ParameterModel</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1, %n parameter(s)</source>
        <translation>
            <numerusform>%1, %n Parameter</numerusform>
            <numerusform>%1, %n Parameter</numerusform>
        </translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>Writing %1 ...</source>
        <translation>%1 wird geschrieben …</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>Geschrieben: %1</translation>
    </message>
    <message>
        <source>Writing %1 failed: %2</source>
        <translation>Schreiben von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Not read</source>
        <translation>Nicht gelesen</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Nicht gelesen: %1</translation>
    </message>
    <message>
        <source>raw %1 = %2h</source>
        <translation>Rohwert %1 = %2h</translation>
    </message>
    <message>
        <source>read-only (read: %1)</source>
        <translation>schreibgeschützt (Lesen: %1)</translation>
    </message>
    <message>
        <source>read: %1, write: %2</source>
        <translation>Lesen: %1, Schreiben: %2</translation>
    </message>
    <message>
        <source>Set 0, or the one value of a parameter that is not set-programmable</source>
        <translation>Satz 0, oder der einzige Wert eines nicht satzprogrammierbaren Parameters</translation>
    </message>
    <message>
        <source>Value / set 0</source>
        <translation>Wert / Satz 0</translation>
    </message>
    <message>
        <source>Set %1</source>
        <translation>Satz %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Vorgabewert</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <source>The drive runs with this set (active set, Fr.02)</source>
        <translation>Der Umrichter arbeitet mit diesem Satz (aktiver Satz, Fr.02)</translation>
    </message>
    <message>
        <source>Value / set 0 (active)</source>
        <translation>Wert / Satz 0 (aktiv)</translation>
    </message>
    <message>
        <source>Set %1 (active)</source>
        <translation>Satz %1 (aktiv)</translation>
    </message>
    <message>
        <source>Last read %1; the drive is not answering</source>
        <translation>Zuletzt gelesen %1; der Umrichter antwortet nicht</translation>
    </message>
    <message>
        <source>Changed in the file: %1; save to keep it</source>
        <translation>In der Datei geändert: %1; speichern, um es zu behalten</translation>
    </message>
    <message>
        <source>Whether the drive took %1 is unknown: %2</source>
        <translation>Ob der Umrichter %1 übernommen hat, ist unbekannt: %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PasswordDialog</name>
    <message>
        <source>Enter Password</source>
        <translation>Passwort eingeben</translation>
    </message>
    <message>
        <source>0 to %1</source>
        <translation>0 bis %1</translation>
    </message>
    <message>
        <source>Level in force:</source>
        <translation>Gültige Passwortebene:</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>not read yet</source>
        <translation>noch nicht gelesen</translation>
    </message>
    <message>
        <source>Asking the drive ...</source>
        <translation>Der Umrichter wird gefragt …</translation>
    </message>
    <message>
        <source>Not accepted: %1</source>
        <translation>Nicht angenommen: %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlaintextComboBox</name>
    <message>
        <source>no text chosen</source>
        <translation>kein Text gewählt</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantDock</name>
    <message>
        <source>Plant</source>
        <translation>Anlage</translation>
    </message>
    <message>
        <source>No plant open. File &gt; New Plant or Open Plant.</source>
        <translation>Keine Anlage geöffnet. Datei &gt; Neue Anlage oder Anlage öffnen.</translation>
    </message>
    <message>
        <source>Find</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>Search every link for its drives and write the addresses found into the plant file</source>
        <translation>Jede Verbindung nach ihren Umrichtern durchsuchen und die gefundenen Adressen in die Anlagendatei schreiben</translation>
    </message>
    <message>
        <source>Back Up All</source>
        <translation>Alle sichern</translation>
    </message>
    <message>
        <source>Read every drive whole and save it to its file in the backup folder</source>
        <translation>Jeden Umrichter ganz lesen und in seiner Datei im Sicherungsordner speichern</translation>
    </message>
    <message>
        <source>Verify All</source>
        <translation>Alle prüfen</translation>
    </message>
    <message>
        <source>Check every drive&apos;s settings against its file in the backup folder</source>
        <translation>Die Einstellungen jedes Umrichters mit seiner Datei im Sicherungsordner vergleichen</translation>
    </message>
    <message>
        <source>Download All...</source>
        <translation>Alle in die Umrichter laden …</translation>
    </message>
    <message>
        <source>Write each drive&apos;s file to the drive, after a last look at what each would get</source>
        <translation>Die Datei jedes Umrichters in den Umrichter schreiben, nach einem letzten Blick auf das, was jeder erhielte</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Stop every link after the value on its way</source>
        <translation>Jede Verbindung nach dem Wert anhalten, der gerade unterwegs ist</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Vergleichen</translation>
    </message>
    <message>
        <source>Read the two selected drives afresh and compare them side by side</source>
        <translation>Die zwei gewählten Umrichter neu lesen und nebeneinander vergleichen</translation>
    </message>
    <message>
        <source>Add Link...</source>
        <translation>Verbindung hinzufügen …</translation>
    </message>
    <message>
        <source>Add a link to the plant file</source>
        <translation>Der Anlagendatei eine Verbindung hinzufügen</translation>
    </message>
    <message>
        <source>Backup Folder...</source>
        <translation>Sicherungsordner …</translation>
    </message>
    <message>
        <source>Choose where the drives&apos; files are</source>
        <translation>Wählen, wo die Dateien der Umrichter liegen</translation>
    </message>
    <message>
        <source>Cannot make the folder %1.</source>
        <translation>Der Ordner %1 kann nicht angelegt werden.</translation>
    </message>
    <message>
        <source>The backup folder %1 does not exist: back the drives up first, or choose another folder.</source>
        <translation>Der Sicherungsordner %1 existiert nicht: erst die Umrichter sichern oder einen anderen Ordner wählen.</translation>
    </message>
    <message>
        <source>The backup folder %1 does not exist.</source>
        <translation>Der Sicherungsordner %1 existiert nicht.</translation>
    </message>
    <message>
        <source>A job is running on the plant shown; stop it first.</source>
        <translation>Auf der gezeigten Anlage läuft ein Auftrag; erst anhalten.</translation>
    </message>
    <message>
        <source>Backup Folder</source>
        <translation>Sicherungsordner</translation>
    </message>
    <message>
        <source>Link %1 added to %2.</source>
        <translation>Verbindung %1 zu %2 hinzugefügt.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; %2 &amp;mdash; backups in %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; %2 &amp;mdash; Sicherungen in %3</translation>
    </message>
    <message>
        <source>Plant: %1</source>
        <translation>Anlage: %1</translation>
    </message>
    <message>
        <source>%1 opens in the editor.</source>
        <translation>%1 wird im Editor geöffnet.</translation>
    </message>
    <message>
        <source>Select two drives to compare.</source>
        <translation>Zwei Umrichter zum Vergleichen wählen.</translation>
    </message>
    <message>
        <source>Searching every link for its drives...</source>
        <translation>Jede Verbindung wird nach ihren Umrichtern durchsucht …</translation>
    </message>
    <message>
        <source>Backing up every drive...</source>
        <translation>Jeder Umrichter wird gesichert …</translation>
    </message>
    <message>
        <source>Verifying every drive against its file...</source>
        <translation>Jeder Umrichter wird mit seiner Datei verglichen …</translation>
    </message>
    <message>
        <source>Reading every drive to see what a download would write...</source>
        <translation>Jeder Umrichter wird gelesen, um zu sehen, was ein Download schriebe …</translation>
    </message>
    <message>
        <source>Downloading to every drive...</source>
        <translation>Download in jeden Umrichter …</translation>
    </message>
    <message>
        <source>Reading the two drives to compare...</source>
        <translation>Die zwei Umrichter werden zum Vergleich gelesen …</translation>
    </message>
    <message>
        <source>downloaded or already equal</source>
        <translation>geladen oder schon gleich</translation>
    </message>
    <message>
        <source>Download All: Report</source>
        <translation>Alle in die Umrichter laden: Bericht</translation>
    </message>
    <message>
        <source>No drive would be written to: each is already equal to its file, or cannot take it (see why).</source>
        <translation>In keinen Umrichter würde geschrieben: jeder gleicht schon seiner Datei oder kann sie nicht aufnehmen (siehe Grund).</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) would be written to. Look at what each gets, then write.</source>
        <translation>
            <numerusform>In %n Umrichter würde geschrieben. Sehen Sie an, was jeder erhält, dann schreiben.</numerusform>
            <numerusform>In %n Umrichter würde geschrieben. Sehen Sie an, was jeder erhält, dann schreiben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Download All: Last Look</source>
        <translation>Alle in die Umrichter laden: letzter Blick</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>The drives could not be compared: %1</source>
        <translation>Die Umrichter konnten nicht verglichen werden: %1</translation>
    </message>
    <message>
        <source>%1 and %2 read; the compare window shows them side by side.</source>
        <translation>%1 und %2 gelesen; das Vergleichsfenster zeigt sie nebeneinander.</translation>
    </message>
    <message>
        <source>%1. The addresses found were written to %2.</source>
        <translation>%1. Die gefundenen Adressen wurden in %2 geschrieben.</translation>
    </message>
    <message>
        <source>%1. The plant file was not changed: %2</source>
        <translation>%1. Die Anlagendatei wurde nicht geändert: %2</translation>
    </message>
    <message>
        <source>%1 as read at %2</source>
        <translation>%1, gelesen um %2</translation>
    </message>
    <message>
        <source>the editor is connected to this line (%1): disconnect it (Drive &gt; Disconnect) and start again; %2</source>
        <translation>der Editor ist mit dieser Leitung verbunden (%1): trennen Sie ihn (Umrichter &gt; Trennen) und starten Sie erneut; %2</translation>
    </message>
    <message>
        <source>plant download of %1</source>
        <translation>Anlagen-Download: %1</translation>
    </message>
    <message>
        <source>History...</source>
        <translation>Historie …</translation>
    </message>
    <message>
        <source>The backup folder&apos;s revisions: what changed when, two side by side, and a revision restored</source>
        <translation>Die Revisionen des Sicherungsordners: was sich wann geändert hat, zwei nebeneinander, und eine Revision wiederhergestellt</translation>
    </message>
    <message>
        <source>plant download of %1 at revision %2</source>
        <translation>Anlagen-Download: %1 in Revision %2</translation>
    </message>
    <message>
        <source>A job is running on the plant; restore once it is done.</source>
        <translation>Auf der Anlage läuft ein Auftrag; erst nach seinem Ende wiederherstellen.</translation>
    </message>
    <message>
        <source>Reading every drive to see what restoring %1 would write...</source>
        <translation>Jeder Umrichter wird gelesen, um zu sehen, was die Wiederherstellung von %1 schriebe …</translation>
    </message>
    <message>
        <source>Restore to %1: Report</source>
        <translation>Wiederherstellen von %1: Bericht</translation>
    </message>
    <message>
        <source>Restore to %1: Last Look</source>
        <translation>Wiederherstellen von %1: letzter Blick</translation>
    </message>
    <message>
        <source>A job is running on the plant; start again once it is done.</source>
        <translation>Auf der Anlage läuft ein Auftrag; nach seinem Ende erneut starten.</translation>
    </message>
    <message>
        <source>A job is running on the plant; compare once it is done.</source>
        <translation>Auf der Anlage läuft ein Auftrag; erst nach seinem Ende vergleichen.</translation>
    </message>
    <message>
        <source>The plant has no drive %1.</source>
        <translation>Die Anlage hat keinen Umrichter %1.</translation>
    </message>
    <message>
        <source>%1 and %2 side by side in the compare window.</source>
        <translation>%1 und %2 nebeneinander im Vergleichsfenster.</translation>
    </message>
    <message>
        <source>Commit to History</source>
        <translation>In Historie übernehmen</translation>
    </message>
    <message>
        <source>Make each Back Up All a revision of the backup folder&apos;s git repository, with what changed since the last one</source>
        <translation>Jedes „Alle sichern“ als Revision im Git-Repository des Sicherungsordners ablegen, mit dem, was sich seit der letzten geändert hat</translation>
    </message>
    <message>
        <source>%1 Stopped: nothing committed.</source>
        <translation>%1 Angehalten: nichts übernommen.</translation>
    </message>
    <message>
        <source>%1 Committing to the history...</source>
        <translation>%1 Wird in die Historie übernommen …</translation>
    </message>
    <message>
        <source>%1 Not committed: %2</source>
        <translation>%1 Nicht übernommen: %2</translation>
    </message>
    <message>
        <source>%1 No drive saved: nothing committed.</source>
        <translation>%1 Kein Umrichter gesichert: nichts übernommen.</translation>
    </message>
    <message>
        <source>%1 No setting changed since the last revision: nothing committed.</source>
        <translation>%1 Seit der letzten Revision hat sich keine Einstellung geändert: nichts übernommen.</translation>
    </message>
    <message>
        <source>%1 Committed %2: %3</source>
        <translation>%1 Übernommen als %2: %3</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantFeature</name>
    <message>
        <source>Plant files (*.json);;All files (*)</source>
        <translation>Anlagendateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;New Plant...</source>
        <translation>&amp;Neue Anlage …</translation>
    </message>
    <message>
        <source>Name a machine and its first link, and save it as a plant file</source>
        <translation>Eine Maschine und ihre erste Verbindung benennen und als Anlagendatei speichern</translation>
    </message>
    <message>
        <source>Open &amp;Plant...</source>
        <translation>Anla&amp;ge öffnen …</translation>
    </message>
    <message>
        <source>Show a plant file&apos;s links and drives in the plant view</source>
        <translation>Die Verbindungen und Umrichter einer Anlagendatei in der Anlagenansicht zeigen</translation>
    </message>
    <message>
        <source>Open Plant</source>
        <translation>Anlage öffnen</translation>
    </message>
    <message>
        <source>Open &amp;Recent Plant</source>
        <translation>&amp;Zuletzt geöffnete Anlagen</translation>
    </message>
    <message>
        <source>Pla&amp;nt View</source>
        <translation>An&amp;lagenansicht</translation>
    </message>
    <message>
        <source>Could not open the plant: %1</source>
        <translation>Die Anlage konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Save New Plant</source>
        <translation>Neue Anlage speichern</translation>
    </message>
    <message>
        <source>Plant Hist&amp;ory...</source>
        <translation>Anlagen&amp;historie …</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantHistoryWindow</name>
    <message>
        <source>Plant History - DriveDesk</source>
        <translation>Anlagenhistorie - DriveDesk</translation>
    </message>
    <message>
        <source>every drive</source>
        <translation>jeder Umrichter</translation>
    </message>
    <message>
        <source>Only the revisions that changed this drive (cabinet-5)</source>
        <translation>Nur die Revisionen, die diesen Umrichter geändert haben (cabinet-5)</translation>
    </message>
    <message>
        <source>&amp;Drive:</source>
        <translation>&amp;Umrichter:</translation>
    </message>
    <message>
        <source>every parameter</source>
        <translation>jeder Parameter</translation>
    </message>
    <message>
        <source>Only the revisions that changed this parameter (op.28)</source>
        <translation>Nur die Revisionen, die diesen Parameter geändert haben (op.28)</translation>
    </message>
    <message>
        <source>&amp;Parameter:</source>
        <translation>&amp;Parameter:</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>A&amp;ktualisieren</translation>
    </message>
    <message>
        <source>Read the backup folder&apos;s revisions again</source>
        <translation>Die Revisionen des Sicherungsordners neu lesen</translation>
    </message>
    <message>
        <source>Revision</source>
        <translation>Revision</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Author</source>
        <translation>Autor</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Nachricht</translation>
    </message>
    <message>
        <source>Changes</source>
        <translation>Änderungen</translation>
    </message>
    <message>
        <source>What the revision selected changed against the one before</source>
        <translation>Was die gewählte Revision gegenüber der vorigen geändert hat</translation>
    </message>
    <message>
        <source>Drive to co&amp;mpare:</source>
        <translation>Zu verglei&amp;chender Umrichter:</translation>
    </message>
    <message>
        <source>&amp;Side by Side</source>
        <translation>&amp;Nebeneinander</translation>
    </message>
    <message>
        <source>The drive&apos;s file at the two revisions selected, or at the one selected and in the backup folder now, side by side in the compare window</source>
        <translation>Die Datei des Umrichters in den zwei gewählten Revisionen, oder in der gewählten und jetzt im Sicherungsordner, nebeneinander im Vergleichsfenster</translation>
    </message>
    <message>
        <source>Against the Dri&amp;ve</source>
        <translation>&amp;Gegen den Umrichter</translation>
    </message>
    <message>
        <source>The drive&apos;s file at the revision selected against the drive itself, read afresh, side by side in the compare window</source>
        <translation>Die Datei des Umrichters in der gewählten Revision gegen den Umrichter selbst, neu gelesen, nebeneinander im Vergleichsfenster</translation>
    </message>
    <message>
        <source>&amp;Restore to This Revision...</source>
        <translation>&amp;Diese Revision wiederherstellen …</translation>
    </message>
    <message>
        <source>Download the revision&apos;s files to the drives, after Download All&apos;s last look at what each would get</source>
        <translation>Die Dateien der Revision in die Umrichter laden, nach dem letzten Blick von „Alle in die Umrichter laden“ auf das, was jeder bekäme</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; revisions of the backups in %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; &amp;mdash; Revisionen der Sicherungen in %2</translation>
    </message>
    <message>
        <source>Reading the revisions...</source>
        <translation>Die Revisionen werden gelesen …</translation>
    </message>
    <message>
        <source>No history to show: %1</source>
        <translation>Keine Historie zu zeigen: %1</translation>
    </message>
    <message>
        <source>%1 has no revisions yet: each backup committed with drivedesk-cli plant backup --commit becomes one.</source>
        <translation>%1 hat noch keine Revisionen: jede mit drivedesk-cli plant backup --commit eingetragene Sicherung wird eine.</translation>
    </message>
    <message>
        <source>No revision changed the drive or parameter the filter names.</source>
        <translation>Keine Revision hat den Umrichter oder Parameter geändert, den der Filter nennt.</translation>
    </message>
    <message>
        <source>Revisions: %1, newest first.</source>
        <translation>Revisionen: %1, die neueste zuerst.</translation>
    </message>
    <message>
        <source>Select one or two revisions and a drive to compare.</source>
        <translation>Eine oder zwei Revisionen und einen Umrichter zum Vergleichen wählen.</translation>
    </message>
    <message>
        <source>Select one revision to restore.</source>
        <translation>Eine Revision zum Wiederherstellen wählen.</translation>
    </message>
    <message>
        <source>Reading the revision&apos;s files...</source>
        <translation>Die Dateien der Revision werden gelesen …</translation>
    </message>
    <message>
        <source>The revision&apos;s files could not be read: %1</source>
        <translation>Die Dateien der Revision konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>%1 goes to Download All: look at what each drive would get, then write.</source>
        <translation>%1 geht an „Alle in die Umrichter laden“: ansehen, was jeder Umrichter bekäme, dann schreiben.</translation>
    </message>
    <message>
        <source>%1 in the backup folder now</source>
        <translation>%1 jetzt im Sicherungsordner</translation>
    </message>
    <message>
        <source>%1 has no file there: %2</source>
        <translation>%1 hat dort keine Datei: %2</translation>
    </message>
    <message>
        <source>Reading %1 to compare it with %2...</source>
        <translation>%1 wird gelesen, um ihn mit %2 zu vergleichen …</translation>
    </message>
    <message>
        <source>%1 and %2 side by side in the compare window.</source>
        <translation>%1 und %2 nebeneinander im Vergleichsfenster.</translation>
    </message>
    <message>
        <source>%1 at %2 (%3)</source>
        <translation>%1 in %2 (%3)</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantLinkDialog</name>
    <message>
        <source>New Plant</source>
        <translation>Neue Anlage</translation>
    </message>
    <message>
        <source>Add Link</source>
        <translation>Verbindung hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Machine:</source>
        <translation>&amp;Maschine:</translation>
    </message>
    <message>
        <source>cabinet</source>
        <translation>Schrank</translation>
    </message>
    <message>
        <source>Names the link in reports and in the names of the drives&apos; files</source>
        <translation>Benennt die Verbindung in Berichten und in den Dateinamen der Umrichter</translation>
    </message>
    <message>
        <source>Link &amp;name:</source>
        <translation>&amp;Name der Verbindung:</translation>
    </message>
    <message>
        <source>tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>tcp:HOST:PORT, serial:GERÄT oder sim</translation>
    </message>
    <message>
        <source>Connec&amp;t:</source>
        <translation>&amp;Verbindung:</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>&amp;Protokoll:</translation>
    </message>
    <message>
        <source>the protocol&apos;s default</source>
        <translation>Vorgabe des Protokolls</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baudrate:</translation>
    </message>
    <message>
        <source>2, 5, 9; empty: search the bus</source>
        <translation>2, 5, 9; leer: den Bus durchsuchen</translation>
    </message>
    <message>
        <source>DIN66019(II): the drive addresses on the bus. HSP5 has one drive a line and no addresses.</source>
        <translation>DIN66019(II): die Umrichteradressen am Bus. HSP5 hat einen Umrichter je Leitung und keine Adressen.</translation>
    </message>
    <message>
        <source>&amp;Addresses:</source>
        <translation>&amp;Adressen:</translation>
    </message>
    <message>
        <source>The baud rate &apos;%1&apos; is not a whole number.</source>
        <translation>Die Baudrate &apos;%1&apos; ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>The address &apos;%1&apos; is not a whole number.</source>
        <translation>Die Adresse &apos;%1&apos; ist keine ganze Zahl.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantLinkRun</name>
    <message>
        <source>refused, nothing written: %1</source>
        <translation>abgelehnt, nichts geschrieben: %1</translation>
    </message>
    <message>
        <source>not everything was written; the report says what the drive holds</source>
        <translation>nicht alles wurde geschrieben; der Bericht sagt, was der Umrichter enthält</translation>
    </message>
    <message>
        <source>%1 does not exist</source>
        <translation>%1 gibt es nicht</translation>
    </message>
    <message>
        <source>cannot connect: %1</source>
        <translation>keine Verbindung möglich: %1</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>verbinde</translation>
    </message>
    <message>
        <source>searching</source>
        <translation>suche</translation>
    </message>
    <message>
        <source>no drive answered</source>
        <translation>kein Umrichter hat geantwortet</translation>
    </message>
    <message>
        <source>the search stopped: %1</source>
        <translation>die Suche wurde beendet: %1</translation>
    </message>
    <message>
        <source>the search was stopped after %1 of %2 addresses</source>
        <translation>die Suche wurde nach %1 von %2 Adressen angehalten</translation>
    </message>
    <message>
        <source>stopped before it was read</source>
        <translation>angehalten, bevor er gelesen wurde</translation>
    </message>
    <message>
        <source>the connection was lost: %1</source>
        <translation>die Verbindung ging verloren: %1</translation>
    </message>
    <message>
        <source>DIN66019 carries parameter values only: the drive has no parameter list to read or write; use din66019ii</source>
        <translation>DIN66019 überträgt nur Parameterwerte: es gibt keine Parameterliste zu lesen oder zu schreiben; din66019ii verwenden</translation>
    </message>
    <message>
        <source>stopped before the drive was read whole; nothing saved</source>
        <translation>angehalten, bevor der Umrichter ganz gelesen war; nichts gesichert</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantModel</name>
    <message>
        <source>not searched</source>
        <translation>nicht gesucht</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>antwortet</translation>
    </message>
    <message>
        <source>unreachable</source>
        <translation>nicht erreichbar</translation>
    </message>
    <message>
        <source>, %1 baud</source>
        <translation>, %1 Baud</translation>
    </message>
    <message>
        <source>%1 on %2%3</source>
        <translation>%1 über %2%3</translation>
    </message>
    <message>
        <source>Double-click to open the drive in the editor</source>
        <translation>Doppelklick öffnet den Umrichter im Editor</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message numerus="yes">
        <source>differs from its file: %n setting(s)</source>
        <translation>
            <numerusform>weicht von seiner Datei ab: %n Einstellung</numerusform>
            <numerusform>weicht von seiner Datei ab: %n Einstellungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>saved, %n parameter(s)</source>
        <translation>
            <numerusform>gesichert, %n Parameter</numerusform>
            <numerusform>gesichert, %n Parameter</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source> set %1</source>
        <translation> Satz %1</translation>
    </message>
    <message>
        <source>%1 %2%3: file %4, drive %5</source>
        <translation>%1 %2%3: Datei %4, Umrichter %5</translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message>
        <source>only in the file</source>
        <translation>nur in der Datei</translation>
    </message>
    <message>
        <source>only on the drive</source>
        <translation>nur im Umrichter</translation>
    </message>
    <message>
        <source>Link / drive</source>
        <translation>Verbindung / Umrichter</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Identification</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>Last backup</source>
        <translation>Letzte Sicherung</translation>
    </message>
    <message>
        <source>Last result</source>
        <translation>Letztes Ergebnis</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>Fortschritt</translation>
    </message>
    <message>
        <source>reading</source>
        <translation>lese</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PlantReportDialog</name>
    <message>
        <source>Drive</source>
        <translation>Umrichter</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>&amp;Write to the Drives</source>
        <translation>In die Umrichter &amp;schreiben</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PollingController</name>
    <message>
        <source>Polling stopped: the connection to the drive was lost</source>
        <translation>Zyklisches Lesen angehalten: die Verbindung zum Umrichter ist abgebrochen</translation>
    </message>
    <message>
        <source>Polling stopped: disconnected from the drive</source>
        <translation>Zyklisches Lesen angehalten: vom Umrichter getrennt</translation>
    </message>
    <message>
        <source>Nothing to poll: this drive has no readable values in group %1</source>
        <translation>Nichts zyklisch zu lesen: dieser Umrichter hat keine lesbaren Werte in Gruppe %1</translation>
    </message>
    <message>
        <source>Polling: %1</source>
        <translation>Zyklisches Lesen: %1</translation>
    </message>
    <message numerus="yes">
        <source>Polling: %n value(s) could not be read (first: %1: %2)</source>
        <translation>
            <numerusform>Zyklisches Lesen: %n Wert konnte nicht gelesen werden (erster: %1: %2)</numerusform>
            <numerusform>Zyklisches Lesen: %n Werte konnten nicht gelesen werden (erster: %1: %2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::PollingFeature</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>&amp;Poll Live Values</source>
        <translation>&amp;Istwerte zyklisch lesen</translation>
    </message>
    <message>
        <source>Read the run display (ru) again and again</source>
        <translation>Die Betriebsanzeige (ru) fortlaufend lesen</translation>
    </message>
    <message>
        <source>Every %1</source>
        <translation>Alle %1</translation>
    </message>
    <message>
        <source>How often the live values are read</source>
        <translation>Wie oft die Istwerte gelesen werden</translation>
    </message>
    <message>
        <source>Polling &amp;Interval</source>
        <translation>&amp;Leseintervall</translation>
    </message>
</context>
<context>
    <name>DriveDesk::PseudoTerminal</name>
    <message>
        <source>no path given for the pseudo-terminal link</source>
        <translation>kein Pfad für den Pseudoterminal-Link angegeben</translation>
    </message>
    <message>
        <source>%1 already exists; choose another path or remove it</source>
        <translation>%1 existiert bereits; einen anderen Pfad wählen oder ihn entfernen</translation>
    </message>
    <message>
        <source>cannot create the link %1: %2</source>
        <translation>der Link %1 kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>the pseudo-terminal was closed</source>
        <translation>das Pseudoterminal wurde geschlossen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::RecentConnections</name>
    <message>
        <source>%1, address %2</source>
        <translation>%1, Adresse %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SaveDriveFeature</name>
    <message>
        <source>Save &amp;Drive to File...</source>
        <translation>Umrichter in &amp;Datei sichern …</translation>
    </message>
    <message>
        <source>Read the drive afresh and save it to a parameter file once every value was read; the window goes on with the drive</source>
        <translation>Den Umrichter neu lesen und in einer Parameterdatei sichern, sobald jeder Wert gelesen ist; das Fenster bleibt beim Umrichter</translation>
    </message>
    <message>
        <source>Save Drive to File</source>
        <translation>Umrichter in Datei sichern</translation>
    </message>
    <message>
        <source>Saving the drive to %1: %2</source>
        <translation>Sichere den Umrichter in %1: %2</translation>
    </message>
    <message>
        <source>Saving the drive to %1: reading the drive...</source>
        <translation>Sichere den Umrichter in %1: lese den Umrichter …</translation>
    </message>
    <message>
        <source>Save Drive to File cancelled: nothing was saved to %1.</source>
        <translation>Umrichter in Datei sichern abgebrochen: nichts wurde in %1 gesichert.</translation>
    </message>
    <message>
        <source>The drive was not saved to %1: %2.</source>
        <translation>Der Umrichter wurde nicht in %1 gesichert: %2.</translation>
    </message>
    <message>
        <source>Not read:</source>
        <translation>Nicht gelesen:</translation>
    </message>
    <message numerus="yes">
        <source>... and %n more (Show Details...)</source>
        <translation>
            <numerusform>… und %n weiterer (Details anzeigen …)</numerusform>
            <numerusform>… und %n weitere (Details anzeigen …)</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not save %1: %2. The file on disk is as it was.</source>
        <translation>%1 konnte nicht gespeichert werden: %2. Die Datei auf dem Datenträger ist unverändert.</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n parameter(s) of the drive to %1.</source>
        <translation>
            <numerusform>%n Parameter des Umrichters in %1 gesichert.</numerusform>
            <numerusform>%n Parameter des Umrichters in %1 gesichert.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScaledSpinBox</name>
    <message>
        <source>%1 .. %2</source>
        <translation>%1 .. %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeChannelPanel</name>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Colour of channel %1</source>
        <translation>Farbe von Kanal %1</translation>
    </message>
    <message>
        <source>Show channel %1</source>
        <translation>Kanal %1 anzeigen</translation>
    </message>
    <message>
        <source>Own axis</source>
        <translation>Eigene Achse</translation>
    </message>
    <message>
        <source>Give channel %1 a value axis of its own on the right</source>
        <translation>Kanal %1 eine eigene Werteachse rechts geben</translation>
    </message>
    <message>
        <source>As the drive has it</source>
        <translation>Wie im Umrichter eingestellt</translation>
    </message>
    <message>
        <source>The parameter the drive delivers on channel %1</source>
        <translation>Der Parameter, den der Umrichter auf Kanal %1 liefert</translation>
    </message>
    <message>
        <source>This drive&apos;s channels cannot be assigned from here: they are recorded as the drive has them.</source>
        <translation>Die Kanäle dieses Umrichters lassen sich von hier nicht zuweisen: sie werden aufgezeichnet, wie der Umrichter sie eingestellt hat.</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Channel %1 carries 16 bits: this parameter&apos;s values beyond -32768..32767 arrive cut to their low 16 bits.</source>
        <translation>Kanal %1 überträgt 16 Bit: Werte dieses Parameters außerhalb von -32768..32767 kommen auf ihre unteren 16 Bit gekürzt an.</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Satz</translation>
    </message>
    <message>
        <source>The parameter set the drive reads channel %1 from</source>
        <translation>Der Parametersatz, aus dem der Umrichter Kanal %1 liest</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeChannelsJob</name>
    <message>
        <source>This drive has no channel-assignment parameters (Sy.16 to Sy.23): its channels are recorded as it has them assigned.</source>
        <translation>Dieser Umrichter hat keine Parameter zur Kanalzuweisung (Sy.16 bis Sy.23): seine Kanäle werden aufgezeichnet, wie er sie zugewiesen hat.</translation>
    </message>
    <message>
        <source>Channel %1: %2 may not be recorded (the drive does not permit it as process data).</source>
        <translation>Kanal %1: %2 kann nicht aufgezeichnet werden (der Umrichter erlaubt ihn nicht als Prozessdatum).</translation>
    </message>
    <message>
        <source>Channel %1: choose at least one set.</source>
        <translation>Kanal %1: wählen Sie mindestens einen Satz.</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeChart</name>
    <message>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>Could not write the image %1.</source>
        <translation>Das Bild %1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Could not write the PDF file %1.</source>
        <translation>Die PDF-Datei %1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>No file name was given.</source>
        <translation>Es wurde kein Dateiname angegeben.</translation>
    </message>
    <message>
        <source>Cannot save %1: the folder %2 does not exist.</source>
        <translation>%1 kann nicht gespeichert werden: der Ordner %2 existiert nicht.</translation>
    </message>
    <message>
        <source>Cannot save %1: the folder %2 is not writable.</source>
        <translation>%1 kann nicht gespeichert werden: in den Ordner %2 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Cannot save %1: it is a folder.</source>
        <translation>%1 kann nicht gespeichert werden: es ist ein Ordner.</translation>
    </message>
    <message>
        <source>Cannot save %1: the file is read-only.</source>
        <translation>%1 kann nicht gespeichert werden: die Datei ist schreibgeschützt.</translation>
    </message>
    <message>
        <source>Wheel: zoom the time; Ctrl+wheel: zoom the values
Drag: move the time; Ctrl+drag: move the values
Shift+click: place cursor 1; Shift+right click: place cursor 2; drag a cursor to move it
+ and -: zoom the time (with Ctrl: the values); Left and Right: move the time; Up and Down: move the values
Home: the whole recording; End: follow the newest samples; A: fit the values; Space: freeze or go on; Esc: remove the cursors</source>
        <translation>Mausrad: Zeit zoomen; Strg+Mausrad: Werte zoomen
Ziehen: Zeit verschieben; Strg+Ziehen: Werte verschieben
Umschalt+Klick: Cursor 1 setzen; Umschalt+Rechtsklick: Cursor 2 setzen; einen Cursor ziehen, um ihn zu verschieben
+ und -: Zeit zoomen (mit Strg: die Werte); Links und Rechts: Zeit verschieben; Auf und Ab: Werte verschieben
Pos1: die ganze Aufzeichnung; Ende: den neuesten Abtastwerten folgen; A: Werte einpassen; Leertaste: anhalten oder weiter; Esc: Cursor entfernen</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Trigger</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeCursorTable</name>
    <message>
        <source>Cursors</source>
        <translation>Cursor</translation>
    </message>
    <message>
        <source>Cursor 1</source>
        <translation>Cursor 1</translation>
    </message>
    <message>
        <source>Cursor 2</source>
        <translation>Cursor 2</translation>
    </message>
    <message>
        <source>2 − 1</source>
        <comment>cursor 2 minus cursor 1</comment>
        <translation>2 − 1</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeDock</name>
    <message>
        <source>Scope</source>
        <translation>Scope</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Aufzeichnen</translation>
    </message>
    <message>
        <source>Record the drive&apos;s scope data; again to stop (F9)</source>
        <translation>Die Scope-Daten des Umrichters aufzeichnen; noch einmal zum Beenden (F9)</translation>
    </message>
    <message>
        <source>Pause View</source>
        <translation>Ansicht anhalten</translation>
    </message>
    <message>
        <source>Hold the chart still; the recording goes on (Space in the chart)</source>
        <translation>Das Diagramm anhalten; die Aufzeichnung läuft weiter (Leertaste im Diagramm)</translation>
    </message>
    <message>
        <source>Roll</source>
        <translation>Rollen</translation>
    </message>
    <message>
        <source>Follow the newest samples (End in the chart)</source>
        <translation>Den neuesten Abtastwerten folgen (Ende im Diagramm)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How many seconds the rolling view shows</source>
        <translation>Wie viele Sekunden die rollende Ansicht zeigt</translation>
    </message>
    <message>
        <source>Whole</source>
        <translation>Ganz</translation>
    </message>
    <message>
        <source>Show the whole recording (Home in the chart)</source>
        <translation>Die ganze Aufzeichnung zeigen (Pos1 im Diagramm)</translation>
    </message>
    <message>
        <source>Auto-scale</source>
        <translation>Autoskalierung</translation>
    </message>
    <message>
        <source>Fit the value axes to what is shown (A in the chart)</source>
        <translation>Die Werteachsen an das Gezeigte anpassen (A im Diagramm)</translation>
    </message>
    <message>
        <source>Max. rate</source>
        <translation>Max. Rate</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>as fast as the link</source>
        <translation>so schnell wie die Verbindung</translation>
    </message>
    <message>
        <source>Polls a second at most; 0: as fast as the link allows</source>
        <translation>Höchstens so viele Abfragen je Sekunde; 0: so schnell, wie die Verbindung erlaubt</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Open Recording...</source>
        <translation>Aufzeichnung öffnen …</translation>
    </message>
    <message>
        <source>Record to File...</source>
        <translation>In Datei aufzeichnen …</translation>
    </message>
    <message>
        <source>Read Offline Records</source>
        <translation>Offline-Aufzeichnung lesen</translation>
    </message>
    <message>
        <source>Export All as CSV...</source>
        <translation>Alles als CSV exportieren …</translation>
    </message>
    <message>
        <source>Export Visible Range as CSV...</source>
        <translation>Sichtbaren Bereich als CSV exportieren …</translation>
    </message>
    <message>
        <source>Export Chart as PNG...</source>
        <translation>Diagramm als PNG exportieren …</translation>
    </message>
    <message>
        <source>Export Chart as PDF...</source>
        <translation>Diagramm als PDF exportieren …</translation>
    </message>
    <message>
        <source>Trigger</source>
        <translation>Trigger</translation>
    </message>
    <message>
        <source>Single Shot</source>
        <translation>Einzelschuss</translation>
    </message>
    <message>
        <source>Wait for the trigger, record one shot around it and stop</source>
        <translation>Auf den Trigger warten, einen Schuss um ihn herum aufzeichnen und anhalten</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>rising</source>
        <translation>steigend</translation>
    </message>
    <message>
        <source>falling</source>
        <translation>fallend</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Schwelle</translation>
    </message>
    <message>
        <source>Pre-trigger</source>
        <translation>Vortrigger</translation>
    </message>
    <message>
        <source>The share of the shot before the trigger</source>
        <translation>Der Anteil des Schusses vor dem Trigger</translation>
    </message>
    <message>
        <source>Shot</source>
        <translation>Schuss</translation>
    </message>
    <message>
        <source>How long the shot is</source>
        <translation>Wie lang der Schuss ist</translation>
    </message>
    <message>
        <source>Choose the sources and press Record (F9), or open a recording.</source>
        <translation>Wählen Sie die Quellen und drücken Sie Aufzeichnen (F9), oder öffnen Sie eine Aufzeichnung.</translation>
    </message>
    <message>
        <source>Connect to a drive to record, or open a recording.</source>
        <translation>Verbinden Sie sich mit einem Umrichter, um aufzuzeichnen, oder öffnen Sie eine Aufzeichnung.</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln sample(s)</source>
        <translation>
            <numerusform>%1: %Ln Abtastwert</numerusform>
            <numerusform>%1: %Ln Abtastwerte</numerusform>
        </translation>
    </message>
    <message>
        <source>DriveDesk scope recordings (*.%1)</source>
        <translation>DriveDesk-Scope-Aufzeichnungen (*.%1)</translation>
    </message>
    <message>
        <source>Stop the recording before opening another.</source>
        <translation>Beenden Sie die Aufzeichnung, bevor Sie eine andere öffnen.</translation>
    </message>
    <message>
        <source>Open Scope Recording</source>
        <translation>Scope-Aufzeichnung öffnen</translation>
    </message>
    <message>
        <source>Record to File</source>
        <translation>In Datei aufzeichnen</translation>
    </message>
    <message>
        <source>Recordings stay in memory.</source>
        <translation>Aufzeichnungen bleiben im Speicher.</translation>
    </message>
    <message>
        <source>The next recording also goes into %1.</source>
        <translation>Die nächste Aufzeichnung geht auch in %1.</translation>
    </message>
    <message>
        <source>There is nothing recorded to export.</source>
        <translation>Es ist nichts aufgezeichnet, das exportiert werden könnte.</translation>
    </message>
    <message>
        <source>Export Visible Range as CSV</source>
        <translation>Sichtbaren Bereich als CSV exportieren</translation>
    </message>
    <message>
        <source>Export All as CSV</source>
        <translation>Alles als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Nach %1 exportiert.</translation>
    </message>
    <message>
        <source>Export Chart as PDF</source>
        <translation>Diagramm als PDF exportieren</translation>
    </message>
    <message>
        <source>Export Chart as PNG</source>
        <translation>Diagramm als PNG exportieren</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Assigning the channels...</source>
        <translation>Kanäle werden zugewiesen …</translation>
    </message>
    <message>
        <source>The channels could not be assigned: %1</source>
        <translation>Die Kanäle konnten nicht zugewiesen werden: %1</translation>
    </message>
    <message>
        <source>Recording...</source>
        <translation>Aufzeichnung läuft …</translation>
    </message>
    <message>
        <source>Triggered; recording the rest of the shot...</source>
        <translation>Getriggert; der Rest des Schusses wird aufgezeichnet …</translation>
    </message>
    <message>
        <source>%1 samples, %2 Hz (average %3 Hz), %4 lost, %5 failed</source>
        <translation>%1 Abtastwerte, %2 Hz (im Mittel %3 Hz), %4 verloren, %5 fehlgeschlagen</translation>
    </message>
    <message>
        <source>Waiting for the trigger; %1</source>
        <translation>Warte auf den Trigger; %1</translation>
    </message>
    <message>
        <source>%1. Not recording to the file any more: %2</source>
        <translation>%1. Keine Aufzeichnung mehr in die Datei: %2</translation>
    </message>
    <message>
        <source>%1; into %2</source>
        <translation>%1; in %2</translation>
    </message>
    <message numerus="yes">
        <source>Recording stopped: %1. The %Ln sample(s) recorded are kept.</source>
        <translation>
            <numerusform>Aufzeichnung beendet: %1. Der %Ln aufgezeichnete Abtastwert bleibt erhalten.</numerusform>
            <numerusform>Aufzeichnung beendet: %1. Die %Ln aufgezeichneten Abtastwerte bleiben erhalten.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Recorded %Ln sample(s) at %1 Hz on average; %2 lost, %3 failed.</source>
        <translation>
            <numerusform>%Ln Abtastwert mit im Mittel %1 Hz aufgezeichnet; %2 verloren, %3 fehlgeschlagen.</numerusform>
            <numerusform>%Ln Abtastwerte mit im Mittel %1 Hz aufgezeichnet; %2 verloren, %3 fehlgeschlagen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Waiting for the trigger...</source>
        <translation>Warte auf den Trigger …</translation>
    </message>
    <message>
        <source>Reading the offline records...</source>
        <translation>Offline-Aufzeichnung wird gelesen …</translation>
    </message>
    <message>
        <source>The connection went away.</source>
        <translation>Die Verbindung ist weg.</translation>
    </message>
    <message numerus="yes">
        <source>%n offline record(s) read</source>
        <translation>
            <numerusform>%n Offline-Datensatz gelesen</numerusform>
            <numerusform>%n Offline-Datensätze gelesen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n with channel 3 or 4 beyond 16 bits, shown at the nearest 16-bit value</source>
        <translation>
            <numerusform>%n mit Kanal 3 oder 4 jenseits von 16 Bit, mit dem nächsten 16-Bit-Wert gezeigt</numerusform>
            <numerusform>%n mit Kanal 3 oder 4 jenseits von 16 Bit, mit dem nächsten 16-Bit-Wert gezeigt</numerusform>
        </translation>
    </message>
    <message>
        <source>Save Recording As...</source>
        <translation>Aufzeichnung speichern unter …</translation>
    </message>
    <message>
        <source>There is nothing recorded to save.</source>
        <translation>Es ist nichts aufgezeichnet, das gespeichert werden könnte.</translation>
    </message>
    <message>
        <source>Stop the recording before saving it, or use Record to File.</source>
        <translation>Beenden Sie die Aufzeichnung, bevor Sie sie speichern, oder zeichnen Sie in eine Datei auf.</translation>
    </message>
    <message>
        <source>Save Scope Recording</source>
        <translation>Scope-Aufzeichnung speichern</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>In %1 gespeichert.</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>%1 kann nicht gespeichert werden: %2</translation>
    </message>
    <message numerus="yes">
        <source>Shot of %Ln sample(s) around the trigger.</source>
        <translation>
            <numerusform>Aufnahme von %Ln Abtastwert um den Trigger.</numerusform>
            <numerusform>Aufnahme von %Ln Abtastwerten um den Trigger.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 Saved to %2.</source>
        <translation>%1 In %2 gesichert.</translation>
    </message>
    <message>
        <source>The recording shown is not saved. The offline records replace it.</source>
        <translation>Die angezeigte Aufzeichnung ist nicht gesichert. Die Offline-Aufzeichnungen ersetzen sie.</translation>
    </message>
    <message>
        <source>The recording shown is not saved. The recording opened replaces it.</source>
        <translation>Die gezeigte Aufzeichnung ist nicht gespeichert. Die geöffnete Aufzeichnung ersetzt sie.</translation>
    </message>
    <message>
        <source>Save it first?</source>
        <translation>Erst speichern?</translation>
    </message>
    <message>
        <source>&amp;Save...</source>
        <translation>&amp;Speichern …</translation>
    </message>
    <message>
        <source>The recording shown is not saved. A new recording replaces it.</source>
        <translation>Die gezeigte Aufzeichnung ist nicht gespeichert. Eine neue Aufzeichnung ersetzt sie.</translation>
    </message>
    <message>
        <source>Close DriveDesk</source>
        <translation>DriveDesk schließen</translation>
    </message>
    <message>
        <source>The scope recording shown is not saved. Closing DriveDesk loses it.</source>
        <translation>Die gezeigte Scope-Aufzeichnung ist nicht gespeichert. Beim Schließen von DriveDesk geht sie verloren.</translation>
    </message>
    <message>
        <source>A math channel cannot be computed: %1</source>
        <translation>Ein Mathe-Kanal kann nicht berechnet werden: %1</translation>
    </message>
    <message>
        <source>Add Math Channel...</source>
        <translation>Mathe-Kanal hinzufügen …</translation>
    </message>
    <message>
        <source>Remove Math Channels</source>
        <translation>Mathe-Kanäle entfernen</translation>
    </message>
    <message>
        <source>Overlay Recording...</source>
        <translation>Aufzeichnung überlagern …</translation>
    </message>
    <message>
        <source>Align Overlay at Trigger</source>
        <translation>Überlagerung am Trigger ausrichten</translation>
    </message>
    <message>
        <source>Align Overlay at Start</source>
        <translation>Überlagerung am Anfang ausrichten</translation>
    </message>
    <message>
        <source>Remove Overlay</source>
        <translation>Überlagerung entfernen</translation>
    </message>
    <message>
        <source>Overlay Scope Recording</source>
        <translation>Scope-Aufzeichnung überlagern</translation>
    </message>
    <message>
        <source>Reading %1 to draw it over the recording...</source>
        <translation>%1 wird gelesen, um es über die Aufzeichnung zu legen …</translation>
    </message>
    <message>
        <source>The overlay is removed.</source>
        <translation>Die Überlagerung ist entfernt.</translation>
    </message>
    <message numerus="yes">
        <source>%1 (%Ln sample(s)) drawn over the recording, aligned at its trigger.</source>
        <translation>
            <numerusform>%1 (%Ln Abtastwert) über die Aufzeichnung gelegt, am Trigger ausgerichtet.</numerusform>
            <numerusform>%1 (%Ln Abtastwerte) über die Aufzeichnung gelegt, am Trigger ausgerichtet.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 (%Ln sample(s)) drawn over the recording, aligned at its start.</source>
        <translation>
            <numerusform>%1 (%Ln Abtastwert) über die Aufzeichnung gelegt, am Anfang ausgerichtet.</numerusform>
            <numerusform>%1 (%Ln Abtastwerte) über die Aufzeichnung gelegt, am Anfang ausgerichtet.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 Not at the trigger: %2.</source>
        <translation>%1 Nicht am Trigger: %2.</translation>
    </message>
    <message>
        <source>Presets</source>
        <translation>Vorlagen</translation>
    </message>
    <message>
        <source>Save the channels, trigger, roll and rate limit under a name, or load a set-up saved for this kind of drive</source>
        <translation>Kanäle, Trigger, Rollen und Ratengrenze unter einem Namen speichern oder eine für diese Art Umrichter gespeicherte Einstellung laden</translation>
    </message>
    <message>
        <source>Save Preset As...</source>
        <translation>Vorlage speichern unter …</translation>
    </message>
    <message>
        <source>Connect to a drive to load its presets</source>
        <translation>Mit einem Umrichter verbinden, um seine Vorlagen zu laden</translation>
    </message>
    <message>
        <source>%1 (plant)</source>
        <translation>%1 (Anlage)</translation>
    </message>
    <message>
        <source>No presets for this kind of drive</source>
        <translation>Keine Vorlagen für diese Art Umrichter</translation>
    </message>
    <message>
        <source>Some presets cannot be read: %1</source>
        <translation>Einige Vorlagen sind nicht lesbar: %1</translation>
    </message>
    <message>
        <source>Save Preset</source>
        <translation>Vorlage speichern</translation>
    </message>
    <message>
        <source>Name of the preset for this kind of drive:</source>
        <translation>Name der Vorlage für diese Art Umrichter:</translation>
    </message>
    <message>
        <source>Name of the preset, kept beside the plant %1:</source>
        <translation>Name der Vorlage, abgelegt neben der Anlage %1:</translation>
    </message>
    <message>
        <source>Preset &apos;%1&apos; saved in %2.</source>
        <translation>Vorlage „%1“ gespeichert in %2.</translation>
    </message>
    <message>
        <source>A preset needs a name.</source>
        <translation>Eine Vorlage braucht einen Namen.</translation>
    </message>
    <message>
        <source>Preset &apos;%1&apos; loaded.</source>
        <translation>Vorlage „%1“ geladen.</translation>
    </message>
    <message>
        <source>Preset &apos;%1&apos; loaded, but: %2</source>
        <translation>Vorlage „%1“ geladen, aber: %2</translation>
    </message>
    <message>
        <source>Channel %1 (%2): %3</source>
        <translation>Kanal %1 (%2): %3</translation>
    </message>
    <message>
        <source>A preset named &apos;%1&apos; is already saved in %2. Replace it?</source>
        <translation>Eine Vorlage „%1“ ist in %2 bereits gespeichert. Ersetzen?</translation>
    </message>
    <message>
        <source>&amp;Replace</source>
        <translation>&amp;Ersetzen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeFeature</name>
    <message>
        <source>&amp;Scope</source>
        <translation>&amp;Scope</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeMathDialog</name>
    <message>
        <source>Add Math Channel</source>
        <translation>Mathe-Kanal hinzufügen</translation>
    </message>
    <message>
        <source>Derivative (d/dt)</source>
        <translation>Ableitung (d/dt)</translation>
    </message>
    <message>
        <source>Integral over time</source>
        <translation>Integral über die Zeit</translation>
    </message>
    <message>
        <source>Difference (first − second)</source>
        <translation>Differenz (erster − zweiter)</translation>
    </message>
    <message>
        <source>Sum (first + second)</source>
        <translation>Summe (erster + zweiter)</translation>
    </message>
    <message>
        <source>Moving average</source>
        <translation>Gleitender Mittelwert</translation>
    </message>
    <message>
        <source>&amp;Kind:</source>
        <translation>&amp;Art:</translation>
    </message>
    <message>
        <source>&amp;Channel:</source>
        <translation>&amp;Kanal:</translation>
    </message>
    <message>
        <source>&amp;Second channel:</source>
        <translation>&amp;Zweiter Kanal:</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>Abtastwerte</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>&amp;Fenster:</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeMeasurementTable</name>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Peak to peak</source>
        <translation>Spitze-Spitze</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>Effektivwert</translation>
    </message>
    <message>
        <source>Rise time</source>
        <translation>Anstiegszeit</translation>
    </message>
    <message>
        <source>Rise rate</source>
        <translation>Anstiegsrate</translation>
    </message>
    <message>
        <source>Fall time</source>
        <translation>Abfallzeit</translation>
    </message>
    <message>
        <source>Fall rate</source>
        <translation>Abfallrate</translation>
    </message>
    <message>
        <source>Between the cursors, both included. Mean and RMS of the line through the samples; rise and fall between 10 % and 90 % of the span from minimum to maximum.</source>
        <translation>Zwischen den Cursorn, beide eingeschlossen. Mittelwert und Effektivwert der Linie durch die Abtastwerte; Anstieg und Abfall zwischen 10 % und 90 % der Spanne vom Minimum zum Maximum.</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeOfflineJob</name>
    <message>
        <source>This connection cannot read offline records (service 21 needs DIN66019II).</source>
        <translation>Diese Verbindung kann keine Offline-Aufzeichnung lesen (Dienst 21 braucht DIN66019II).</translation>
    </message>
    <message>
        <source>The drive holds no offline records.</source>
        <translation>Der Umrichter hat keine Offline-Aufzeichnung.</translation>
    </message>
    <message>
        <source>Record %1: %2</source>
        <translation>Datensatz %1: %2</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ScopeSpectrumView</name>
    <message>
        <source>Spectrum</source>
        <translation>Spektrum</translation>
    </message>
    <message>
        <source>&amp;Channel</source>
        <translation>&amp;Kanal</translation>
    </message>
    <message>
        <source>&amp;Range</source>
        <translation>&amp;Bereich</translation>
    </message>
    <message>
        <source>the view</source>
        <translation>die Ansicht</translation>
    </message>
    <message>
        <source>between the cursors</source>
        <translation>zwischen den Cursorn</translation>
    </message>
    <message>
        <source>&amp;Logarithmic amplitude</source>
        <translation>&amp;Logarithmische Amplitude</translation>
    </message>
    <message>
        <source>Spectrum...</source>
        <translation>Spektrum …</translation>
    </message>
    <message>
        <source>The amplitude spectrum of a channel over the view or between the cursors (Ctrl+Shift+F)</source>
        <translation>Das Amplitudenspektrum eines Kanals über die Ansicht oder zwischen den Cursorn (Strg+Umschalt+F)</translation>
    </message>
    <message>
        <source>No samples: record or open a recording.</source>
        <translation>Keine Abtastwerte: aufzeichnen oder eine Aufzeichnung öffnen.</translation>
    </message>
    <message>
        <source>Place both cursors on the chart for the range between them.</source>
        <translation>Beide Cursor ins Diagramm setzen, um den Bereich zwischen ihnen zu nehmen.</translation>
    </message>
    <message>
        <source>No spectrum: %1</source>
        <translation>Kein Spektrum: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln sample(s) from %2 s to %3 s, %4 points at %5 Hz, bins of %6 Hz</source>
        <translation>
            <numerusform>%1: %Ln Abtastwert von %2 s bis %3 s, %4 Punkte bei %5 Hz, Stützstellen im Abstand von %6 Hz</numerusform>
            <numerusform>%1: %Ln Abtastwerte von %2 s bis %3 s, %4 Punkte bei %5 Hz, Stützstellen im Abstand von %6 Hz</numerusform>
        </translation>
    </message>
    <message>
        <source> (resampled to even spacing: the samples came unevenly)</source>
        <translation> (auf gleiche Abstände umgerechnet: die Abtastwerte kamen ungleichmäßig)</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SerialLink</name>
    <message>
        <source>no such serial device</source>
        <translation>serielle Schnittstelle nicht vorhanden</translation>
    </message>
    <message>
        <source>permission denied (the port may be in use by another program, or the user may lack access to it)</source>
        <translation>Zugriff verweigert (die Schnittstelle wird vielleicht von einem anderen Programm benutzt, oder dem Benutzer fehlt das Zugriffsrecht)</translation>
    </message>
    <message>
        <source>the port is already open</source>
        <translation>die Schnittstelle ist bereits geöffnet</translation>
    </message>
    <message>
        <source>the device is no longer available (adapter unplugged?)</source>
        <translation>das Gerät ist nicht mehr verfügbar (Adapter abgezogen?)</translation>
    </message>
    <message>
        <source>reading from the port failed</source>
        <translation>Lesen von der Schnittstelle fehlgeschlagen</translation>
    </message>
    <message>
        <source>writing to the port failed</source>
        <translation>Schreiben auf die Schnittstelle fehlgeschlagen</translation>
    </message>
    <message>
        <source>the port does not support these settings</source>
        <translation>die Schnittstelle unterstützt diese Einstellungen nicht</translation>
    </message>
    <message>
        <source>the port is not open</source>
        <translation>die Schnittstelle ist nicht geöffnet</translation>
    </message>
    <message>
        <source>timeout</source>
        <translation>Zeitüberschreitung</translation>
    </message>
    <message>
        <source>unknown serial port error</source>
        <translation>unbekannter Fehler der seriellen Schnittstelle</translation>
    </message>
    <message>
        <source>no serial device given</source>
        <translation>keine serielle Schnittstelle angegeben</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SetsDialog</name>
    <message>
        <source>Write to Sets</source>
        <translation>In Sätze schreiben</translation>
    </message>
    <message>
        <source>Write the value to these sets:</source>
        <translation>Den Wert in diese Sätze schreiben:</translation>
    </message>
    <message>
        <source>&amp;All</source>
        <translation>&amp;Alle</translation>
    </message>
    <message>
        <source>&amp;None</source>
        <translation>&amp;Keine</translation>
    </message>
    <message>
        <source>Copy Set</source>
        <translation>Satz kopieren</translation>
    </message>
    <message>
        <source>Copy every set-programmable value of one set into another:</source>
        <translation>Alle satzprogrammierbaren Werte eines Satzes in einen anderen kopieren:</translation>
    </message>
    <message>
        <source>&amp;From:</source>
        <translation>&amp;Von:</translation>
    </message>
    <message>
        <source>&amp;To:</source>
        <translation>&amp;Nach:</translation>
    </message>
    <message>
        <source>Set %1 (active)</source>
        <translation>Satz %1 (aktiv)</translation>
    </message>
    <message>
        <source>Set %1</source>
        <translation>Satz %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SetsFeature</name>
    <message>
        <source>Fr.02: the set the drive works with. Fr.09: the set that indirect addressing reaches.</source>
        <translation>Fr.02: der Satz, mit dem der Umrichter arbeitet. Fr.09: der Satz, den die indirekte Adressierung erreicht.</translation>
    </message>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
    <message>
        <source>Active set: %1</source>
        <translation>Aktiver Satz: %1</translation>
    </message>
    <message>
        <source>Set pointer (Fr.09): %1</source>
        <translation>Satzzeiger (Fr.09): %1</translation>
    </message>
</context>
<context>
    <name>DriveDesk::SimulatedLink</name>
    <message>
        <source>parity error on a received character</source>
        <translation>Paritätsfehler in einem empfangenen Zeichen</translation>
    </message>
    <message>
        <source>simulated drive</source>
        <translation>simulierter Umrichter</translation>
    </message>
    <message numerus="yes">
        <source>simulated drive(s) %1</source>
        <translation>
            <numerusform>simulierter Umrichter %1</numerusform>
            <numerusform>simulierte Umrichter %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::SimulatorServer</name>
    <message>
        <source>&quot;%1&quot; is not an IP address to listen on (give e.g. 127.0.0.1, localhost or *)</source>
        <translation>„%1“ ist keine IP-Adresse zum Lauschen (z. B. 127.0.0.1, localhost oder * angeben)</translation>
    </message>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>Lauschen auf %1:%2 nicht möglich: %3</translation>
    </message>
</context>
<context>
    <name>DriveDesk::StartupOptions</name>
    <message>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>unerwartetes Argument „%1“</translation>
    </message>
    <message>
        <source>--protocol, --address and --baud belong to --connect: give tcp:HOST:PORT, serial:DEVICE or sim</source>
        <translation>--protocol, --address und --baud gehören zu --connect: tcp:HOST:PORT, serial:GERÄT oder sim angeben</translation>
    </message>
    <message>
        <source>--open shows a parameter file with no drive: leave out --connect, --protocol, --address and --baud</source>
        <translation>--open zeigt eine Parameterdatei ohne Umrichter: --connect, --protocol, --address und --baud weglassen</translation>
    </message>
    <message>
        <source>Usage: drivedesk [--connect TARGET | --open FILE] [options]

The DriveDesk parameter editor. Without --connect or --open it opens the connection
dialog.

  --connect TARGET     tcp:HOST:PORT, serial:DEVICE or sim (the simulated drive)
  --open FILE          show and edit a parameter file with no drive
  --protocol NAME      hsp5 (default), din66019ii or din66019
  --address N          drive address on a DIN66019(II) bus, 0..239 (default 1)
  --baud N|auto        baud rate; auto (the default on a serial line) finds the rate
                       the drive answers at
  --language en|de     language of the window and of the drive&apos;s texts
  --journal PATH       the journal of the values written, instead of
                       ~/.local/share/DriveDesk/journal.sqlite
</source>
        <translation>Aufruf: drivedesk [--connect ZIEL | --open DATEI] [Optionen]

Der DriveDesk-Parametereditor. Ohne --connect oder --open öffnet er den
Verbindungsdialog.

  --connect ZIEL       tcp:HOST:PORT, serial:GERÄT oder sim (der simulierte Umrichter)
  --open DATEI         eine Parameterdatei ohne Umrichter anzeigen und bearbeiten
  --protocol NAME      hsp5 (Vorgabe), din66019ii oder din66019
  --address N          Umrichteradresse an einem DIN66019(II)-Bus, 0..239 (Vorgabe 1)
  --baud N|auto        Baudrate; auto (die Vorgabe an einer seriellen Leitung) findet die
                       Baudrate, bei der der Umrichter antwortet
  --language en|de     Sprache des Fensters und der Texte des Umrichters
  --journal PFAD       das Journal der geschriebenen Werte, statt
                       ~/.local/share/DriveDesk/journal.sqlite
</translation>
    </message>
    <message>
        <source>--journal names a file: give a path</source>
        <translation>--journal nennt eine Datei: einen Pfad angeben</translation>
    </message>
</context>
<context>
    <name>DriveDesk::TcpLink</name>
    <message>
        <source>no answer from the device server within %1 ms</source>
        <translation>keine Antwort vom Geräteserver innerhalb von %1 ms</translation>
    </message>
    <message>
        <source>no host or port given</source>
        <translation>kein Host oder Port angegeben</translation>
    </message>
    <message>
        <source>writing failed (%1)</source>
        <translation>Schreiben fehlgeschlagen (%1)</translation>
    </message>
    <message>
        <source>the device server closed the connection</source>
        <translation>der Geräteserver hat die Verbindung geschlossen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::TelegramMonitor</name>
    <message>
        <source>Telegram monitor</source>
        <translation>Telegramm-Monitor</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Hold new telegrams back and show them on resume</source>
        <translation>Neue Telegramme zurückhalten und beim Fortsetzen anzeigen</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Forget every telegram listed and held</source>
        <translation>Alle angezeigten und zurückgehaltenen Telegramme verwerfen</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern …</translation>
    </message>
    <message>
        <source>Save the telegrams the filter shows to a CSV or text file</source>
        <translation>Die vom Filter gezeigten Telegramme in einer CSV- oder Textdatei speichern</translation>
    </message>
    <message>
        <source>Filter: meaning, hex bytes or characters</source>
        <translation>Filter: Bedeutung, Hex-Bytes oder Zeichen</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>Nur Fehler</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message numerus="yes">
        <source>Saved %Ln telegram(s) to %1.</source>
        <translation>
            <numerusform>%Ln Telegramm in %1 gespeichert.</numerusform>
            <numerusform>%Ln Telegramme in %1 gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Save telegrams</source>
        <translation>Telegramme speichern</translation>
    </message>
    <message>
        <source>Text files (*.txt)</source>
        <translation>Textdateien (*.txt)</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %Ln telegram(s) shown</source>
        <translation>
            <numerusform>%1 von %Ln Telegramm angezeigt</numerusform>
            <numerusform>%1 von %Ln Telegrammen angezeigt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln telegram(s)</source>
        <translation>
            <numerusform>%Ln Telegramm</numerusform>
            <numerusform>%Ln Telegramme</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%Ln older telegram(s) dropped: the monitor keeps the latest %1</source>
        <translation>
            <numerusform>%Ln älteres Telegramm verworfen: der Monitor behält die letzten %1</numerusform>
            <numerusform>%Ln ältere Telegramme verworfen: der Monitor behält die letzten %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>paused: %Ln telegram(s) held, shown on resume</source>
        <translation>
            <numerusform>angehalten: %Ln Telegramm zurückgehalten, wird beim Fortsetzen angezeigt</numerusform>
            <numerusform>angehalten: %Ln Telegramme zurückgehalten, werden beim Fortsetzen angezeigt</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::TrafficModel</name>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n Byte</numerusform>
            <numerusform>%n Bytes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>DriveDesk::UploadRun</name>
    <message>
        <source>no drive is connected</source>
        <translation>kein Umrichter verbunden</translation>
    </message>
    <message>
        <source>the drive stopped answering during the read (no answer after every attempt)</source>
        <translation>der Umrichter antwortete während des Lesens nicht mehr (keine Antwort nach allen Versuchen)</translation>
    </message>
    <message>
        <source>the read ended without a result</source>
        <translation>das Lesen endete ohne Ergebnis</translation>
    </message>
    <message>
        <source>the connection was closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::ValueEdits</name>
    <message>
        <source>the connection to the drive was closed</source>
        <translation>die Verbindung zum Umrichter wurde geschlossen</translation>
    </message>
</context>
<context>
    <name>DriveDesk::WriteJournal</name>
    <message>
        <source>&amp;Journal Every Write</source>
        <translation>Schreibvorgänge im &amp;Journal festhalten</translation>
    </message>
    <message>
        <source>Record every value written to the drive, with the value before and after, in the journal %1</source>
        <translation>Jeden in den Umrichter geschriebenen Wert mit dem Wert davor und danach im Journal %1 festhalten</translation>
    </message>
    <message>
        <source>Every value written is journaled.</source>
        <translation>Jeder geschriebene Wert wird im Journal festgehalten.</translation>
    </message>
    <message>
        <source>Values written are not journaled.</source>
        <translation>Geschriebene Werte werden nicht im Journal festgehalten.</translation>
    </message>
    <message>
        <source>edit</source>
        <translation>Bearbeitung</translation>
    </message>
    <message>
        <source>%1 (Drive &gt; Journal Every Write off writes without it)</source>
        <translation>%1 (Umrichter &gt; Schreibvorgänge im Journal festhalten aus: schreibt ohne Journal)</translation>
    </message>
</context>
<context>
    <name>DriveIdentity</name>
    <message>
        <source>Identification</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>not read: %1</source>
        <translation>nicht gelesen: %1</translation>
    </message>
    <message>
        <source>no value</source>
        <translation>kein Wert</translation>
    </message>
    <message>
        <source>Type %1</source>
        <translation>Typ %1</translation>
    </message>
    <message>
        <source>Type %1, software %2</source>
        <translation>Typ %1, Software %2</translation>
    </message>
    <message>
        <source>Type %1, software %2, serial number %3</source>
        <translation>Typ %1, Software %2, Seriennummer %3</translation>
    </message>
</context>
<context>
    <name>EditCheck</name>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 ist schreibgeschützt</translation>
    </message>
    <message>
        <source>%1 needs password level %2 (in force: %3)</source>
        <translation>%1 braucht die Passwortstufe %2 (gültig: %3)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: no set chosen</source>
        <translation>%1: kein Satz gewählt</translation>
    </message>
</context>
<context>
    <name>EditJournal</name>
    <message>
        <source>not sent: %1</source>
        <translation>nicht gesendet: %1</translation>
    </message>
    <message>
        <source>the journal cannot record it: %1</source>
        <translation>das Journal kann es nicht festhalten: %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>EditText</name>
    <message>
        <source>%1 not reset%2: %3</source>
        <translation>%1 nicht zurückgesetzt%2: %3</translation>
    </message>
    <message>
        <source>%1 = %2 not written%3: %4</source>
        <translation>%1 = %2 nicht geschrieben%3: %4</translation>
    </message>
    <message>
        <source>%1 reset to its default%2</source>
        <translation>%1 auf den Vorgabewert zurückgesetzt%2</translation>
    </message>
    <message>
        <source>%1 = %2 written%3</source>
        <translation>%1 = %2 geschrieben%3</translation>
    </message>
    <message>
        <source>; not%1: %2</source>
        <translation>; nicht%1: %2</translation>
    </message>
    <message>
        <source>; reading it back failed: %1</source>
        <translation>; das Zurücklesen schlug fehl: %1</translation>
    </message>
    <message>
        <source>the drive holds %1%2</source>
        <translation>der Umrichter enthält %1%2</translation>
    </message>
    <message>
        <source>%1 reset%2 unknown: no answer, so whether the drive took it is unknown (%3)</source>
        <translation>%1 zurückgesetzt%2 unbekannt: keine Antwort, ob der Umrichter es übernommen hat, ist unbekannt (%3)</translation>
    </message>
    <message>
        <source>%1 = %2%3 unknown: no answer, so whether the drive took it is unknown (%4)</source>
        <translation>%1 = %2%3 unbekannt: keine Antwort, ob der Umrichter den Wert übernommen hat, ist unbekannt (%4)</translation>
    </message>
    <message>
        <source>; its answer was lost, and reading it back showed it taken</source>
        <translation>; die Antwort ging verloren, das Zurücklesen zeigte den Wert übernommen</translation>
    </message>
    <message>
        <source>; whether the drive took it%1 is unknown: no answer (%2)</source>
        <translation>; ob der Umrichter den Wert%1 übernommen hat, ist unbekannt: keine Antwort (%2)</translation>
    </message>
</context>
<context>
    <name>FindDrivesJob</name>
    <message>
        <source>inverter identifier %1</source>
        <translation>Umrichterkennung %1</translation>
    </message>
    <message>
        <source>software %1</source>
        <translation>Software %1</translation>
    </message>
    <message>
        <source>serial number %1</source>
        <translation>Seriennummer %1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>the addresses %1..%2 hold no drive address (drives are 0..239)</source>
        <translation>die Adressen %1..%2 enthalten keine Umrichteradresse (Umrichter haben 0..239)</translation>
    </message>
    <message>
        <source>drive %1: %2</source>
        <translation>Umrichter %1: %2</translation>
    </message>
    <message>
        <source>drive %1 answered</source>
        <translation>Umrichter %1 hat geantwortet</translation>
    </message>
    <message>
        <source>no drive at %1</source>
        <translation>kein Umrichter an %1</translation>
    </message>
</context>
<context>
    <name>Git</name>
    <message>
        <source>git cannot be run (%1): install git</source>
        <translation>git kann nicht ausgeführt werden (%1): git installieren</translation>
    </message>
    <message>
        <source>git %1 failed with exit code %2</source>
        <translation>git %1 ist mit Exit-Code %2 fehlgeschlagen</translation>
    </message>
    <message>
        <source>git %1 failed: %2</source>
        <translation>git %1 fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>GroupProperties</name>
    <message>
        <source>password level: %1</source>
        <translation>Passwortlevel: %1</translation>
    </message>
    <message>
        <source>visible on the display</source>
        <translation>sichtbar auf der Anzeige</translation>
    </message>
    <message>
        <source>visible in COMBIVIS</source>
        <translation>sichtbar über COMBIVIS</translation>
    </message>
    <message>
        <source>free bit %1 set</source>
        <translation>freies Bit %1 gesetzt</translation>
    </message>
</context>
<context>
    <name>Journal</name>
    <message>
        <source>cannot open the journal %1: Qt&apos;s SQLite driver (QSQLITE) is missing</source>
        <translation>das Journal %1 kann nicht geöffnet werden: der SQLite-Treiber von Qt (QSQLITE) fehlt</translation>
    </message>
    <message>
        <source>cannot write the journal %1: SQLite cannot keep a write-ahead log there (journal mode %2)</source>
        <translation>das Journal %1 kann nicht geschrieben werden: SQLite kann dort kein Write-Ahead-Log führen (Journalmodus %2)</translation>
    </message>
    <message>
        <source>the journal %1 is not open for writing</source>
        <translation>das Journal %1 ist nicht zum Schreiben geöffnet</translation>
    </message>
    <message>
        <source>the journal %1 has no entry %2</source>
        <translation>das Journal %1 hat keinen Eintrag %2</translation>
    </message>
    <message>
        <source>the journal %1 is not open</source>
        <translation>das Journal %1 ist nicht geöffnet</translation>
    </message>
</context>
<context>
    <name>JournalEntryText</name>
    <message>
        <source>written</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <source>refused</source>
        <translation>abgelehnt</translation>
    </message>
    <message>
        <source>refused: %1</source>
        <translation>abgelehnt: %1</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>unknown: %1</source>
        <translation>unbekannt: %1</translation>
    </message>
    <message>
        <source>%1 since %2 by %3</source>
        <translation>%1 seit %2 von %3</translation>
    </message>
    <message>
        <source>%1 since %2 by %3, was %4</source>
        <translation>%1 seit %2 von %3, vorher %4</translation>
    </message>
</context>
<context>
    <name>JournalFilterText</name>
    <message>
        <source>&apos;%1&apos; names no drive: give its serial number, its link (serial:/dev/ttyUSB0) or LINK@ADDRESS (serial:/dev/ttyUSB0@3)</source>
        <translation>&apos;%1&apos; nennt keinen Umrichter: Seriennummer, Verbindung (serial:/dev/ttyUSB0) oder VERBINDUNG@ADRESSE (serial:/dev/ttyUSB0@3) angeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no parameter: give its id like op.28 or its address like 0x0A1C</source>
        <translation>&apos;%1&apos; ist kein Parameter: Kennung wie op.28 oder Adresse wie 0x0A1C angeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is no time: use a date like 2026-11-24 or a date and time like 2026-11-24T10:42 (local time)</source>
        <translation>&apos;%1&apos; ist keine Zeit: ein Datum wie 2026-11-24 oder Datum und Uhrzeit wie 2026-11-24T10:42 (Ortszeit) angeben</translation>
    </message>
</context>
<context>
    <name>JournalFormat</name>
    <message>
        <source>active</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <source>(password)</source>
        <translation>(Passwort)</translation>
    </message>
    <message>
        <source>no entries</source>
        <translation>keine Einträge</translation>
    </message>
    <message>
        <source>#</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Umrichter</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Satz</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <source>Written</source>
        <translation>Geschrieben</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>Zurückgelesen</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Auftrag</translation>
    </message>
</context>
<context>
    <name>JournalProblem</name>
    <message>
        <source>cannot write the journal %1: the folder %2 cannot be made</source>
        <translation>das Journal %1 kann nicht geschrieben werden: der Ordner %2 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>cannot write the journal %1: it is no file</source>
        <translation>das Journal %1 kann nicht geschrieben werden: es ist keine Datei</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the file is read-only</source>
        <translation>das Journal %1 kann nicht geschrieben werden: die Datei ist schreibgeschützt</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the folder %2 is read-only (the journal keeps %3-wal and %3-shm beside it)</source>
        <translation>das Journal %1 kann nicht geschrieben werden: der Ordner %2 ist schreibgeschützt (das Journal legt %3-wal und %3-shm daneben an)</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the disk is full</source>
        <translation>das Journal %1 kann nicht geschrieben werden: der Datenträger ist voll</translation>
    </message>
    <message>
        <source>there is no journal %1</source>
        <translation>es gibt kein Journal %1</translation>
    </message>
    <message>
        <source>cannot read the journal %1: it is no file</source>
        <translation>das Journal %1 kann nicht gelesen werden: es ist keine Datei</translation>
    </message>
    <message>
        <source>cannot read the journal %1: permission denied</source>
        <translation>das Journal %1 kann nicht gelesen werden: Zugriff verweigert</translation>
    </message>
    <message>
        <source>the journal %1 is locked by another program: waited %2 ms for it</source>
        <translation>das Journal %1 ist von einem anderen Programm gesperrt: %2 ms darauf gewartet</translation>
    </message>
    <message>
        <source>cannot write the journal %1: it is read-only (%2)</source>
        <translation>das Journal %1 kann nicht geschrieben werden: es ist schreibgeschützt (%2)</translation>
    </message>
    <message>
        <source>cannot write the journal %1: the disk failed or is full (%2)</source>
        <translation>das Journal %1 kann nicht geschrieben werden: der Datenträger ist defekt oder voll (%2)</translation>
    </message>
    <message>
        <source>cannot open the journal %1 (%2)</source>
        <translation>das Journal %1 kann nicht geöffnet werden (%2)</translation>
    </message>
    <message>
        <source>the journal %1: %2</source>
        <translation>das Journal %1: %2</translation>
    </message>
    <message>
        <source>%1 is no DriveDesk journal: it is damaged or not a journal at all</source>
        <translation>%1 ist kein DriveDesk-Journal: es ist beschädigt oder gar kein Journal</translation>
    </message>
    <message>
        <source>the journal %1 was made by a newer DriveDesk (journal version %2; this one knows up to %3): it is not written</source>
        <translation>das Journal %1 stammt von einem neueren DriveDesk (Journalversion %2; dieses kennt bis %3): es wird nicht geschrieben</translation>
    </message>
</context>
<context>
    <name>JournalRevert</name>
    <message>
        <source>revert</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>revert of entry %1</source>
        <translation>Zurücksetzen von Eintrag %1</translation>
    </message>
    <message>
        <source>revert of entries %1..%2</source>
        <translation>Zurücksetzen der Einträge %1..%2</translation>
    </message>
    <message>
        <source>entry %1: the journal has no such entry</source>
        <translation>Eintrag %1: das Journal hat keinen solchen Eintrag</translation>
    </message>
    <message>
        <source>entry %1 (%2)</source>
        <translation>Eintrag %1 (%2)</translation>
    </message>
    <message>
        <source>%1 was written to another drive (%2), not the one connected (%3)</source>
        <translation>%1 wurde in einen anderen Umrichter (%2) geschrieben, nicht in den verbundenen (%3)</translation>
    </message>
    <message>
        <source>%1 is a password entered: the journal keeps no value of it, so it cannot be reverted</source>
        <translation>%1 ist eine Passworteingabe: das Journal hält keinen Wert davon fest, daher kann sie nicht zurückgesetzt werden</translation>
    </message>
    <message>
        <source>%1: the drive has no such parameter</source>
        <translation>%1: der Umrichter hat keinen solchen Parameter</translation>
    </message>
    <message>
        <source>%1: the value before was not read, so there is none to write back</source>
        <translation>%1: der Wert davor wurde nicht gelesen, daher gibt es keinen zum Zurückschreiben</translation>
    </message>
    <message>
        <source>%1 was written to the active set, and the journal does not say which set that was</source>
        <translation>%1 wurde in den aktiven Satz geschrieben, und das Journal sagt nicht, welcher Satz das war</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no entry: give an entry&apos;s number (12) or a range (12..15)</source>
        <translation>„%1“ nennt keinen Eintrag: eine Eintragsnummer (12) oder einen Bereich (12..15) angeben</translation>
    </message>
    <message>
        <source>the value before entry %1</source>
        <translation>den Wert vor Eintrag %1</translation>
    </message>
    <message>
        <source>the values before the entries</source>
        <translation>die Werte vor den Einträgen</translation>
    </message>
    <message>
        <source>the values before entries %1..%2</source>
        <translation>die Werte vor den Einträgen %1..%2</translation>
    </message>
</context>
<context>
    <name>MetadataCache</name>
    <message>
        <source>not JSON (%1 at byte %2)</source>
        <translation>kein JSON (%1 bei Byte %2)</translation>
    </message>
    <message>
        <source>not a DriveDesk metadata cache file</source>
        <translation>keine Metadaten-Cache-Datei von DriveDesk</translation>
    </message>
    <message>
        <source>cache version %1, this DriveDesk reads version %2</source>
        <translation>Cache-Version %1, dieses DriveDesk liest Version %2</translation>
    </message>
    <message>
        <source>it holds another kind of drive</source>
        <translation>sie enthält eine andere Umrichterart</translation>
    </message>
    <message>
        <source>it has no languages</source>
        <translation>sie enthält keine Sprachen</translation>
    </message>
    <message>
        <source>language %1 holds the texts of language %2</source>
        <translation>Sprache %1 enthält die Texte der Sprache %2</translation>
    </message>
    <message>
        <source>metadata cache file &apos;%1&apos; ignored and removed: %2</source>
        <translation>Metadaten-Cache-Datei „%1“ übergangen und entfernt: %2</translation>
    </message>
    <message>
        <source>cannot create the metadata cache folder &apos;%1&apos;</source>
        <translation>der Metadaten-Cache-Ordner „%1“ kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>cannot remove &apos;%1&apos;</source>
        <translation>„%1“ kann nicht entfernt werden</translation>
    </message>
    <message>
        <source>cannot write the metadata cache: %1</source>
        <translation>der Metadaten-Cache kann nicht geschrieben werden: %1</translation>
    </message>
</context>
<context>
    <name>MetadataMatch</name>
    <message>
        <source>divisor %1, multiplier %2, offset %3, flags %4h</source>
        <translation>Teiler %1, Multiplikator %2, Offset %3, Flags %4h</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>properties 1</source>
        <translation>Eigenschaften 1</translation>
    </message>
    <message>
        <source>properties 2</source>
        <translation>Eigenschaften 2</translation>
    </message>
    <message>
        <source>display scaling</source>
        <translation>Anzeigeskalierung</translation>
    </message>
    <message>
        <source>lower limit</source>
        <translation>untere Grenze</translation>
    </message>
    <message>
        <source>upper limit</source>
        <translation>obere Grenze</translation>
    </message>
    <message>
        <source>id</source>
        <translation>Kürzel</translation>
    </message>
</context>
<context>
    <name>ParameterComparison</name>
    <message>
        <source>?</source>
        <translation>?</translation>
    </message>
</context>
<context>
    <name>ParameterCsv</name>
    <message>
        <source>id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>Satz %1</translation>
    </message>
</context>
<context>
    <name>ParameterDocument</name>
    <message>
        <source>expected an object</source>
        <translation>Objekt erwartet</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>fehlt</translation>
    </message>
    <message>
        <source>expected an integer</source>
        <translation>ganze Zahl erwartet</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 liegt außerhalb von %2..%3</translation>
    </message>
    <message>
        <source>expected a string</source>
        <translation>Zeichenkette erwartet</translation>
    </message>
    <message>
        <source>expected true or false</source>
        <translation>true oder false erwartet</translation>
    </message>
    <message>
        <source>expected an array</source>
        <translation>Array erwartet</translation>
    </message>
    <message>
        <source>unknown field</source>
        <translation>unbekanntes Feld</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names %2, not the address %3</source>
        <translation>„%1“ nennt %2, nicht die Adresse %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not agree with scaling.flags (unit &apos;%2&apos;)</source>
        <translation>„%1“ passt nicht zu scaling.flags (Einheit „%2“)</translation>
    </message>
    <message numerus="yes">
        <source>%1 does not agree with scaling.flags (%n decimals)</source>
        <translation>
            <numerusform>%1 passt nicht zu scaling.flags (%n Nachkommastelle)</numerusform>
            <numerusform>%1 passt nicht zu scaling.flags (%n Nachkommastellen)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 does not agree with properties1 bit 11</source>
        <translation>%1 passt nicht zu properties1 Bit 11</translation>
    </message>
    <message>
        <source>%1 does not agree with properties2 bit 3</source>
        <translation>%1 passt nicht zu properties2 Bit 3</translation>
    </message>
    <message numerus="yes">
        <source>%n entries; a set-programmable parameter has one for each of the 8 sets</source>
        <translation>
            <numerusform>%n Eintrag; ein satzprogrammierbarer Parameter hat einen für jeden der 8 Sätze</numerusform>
            <numerusform>%n Einträge; ein satzprogrammierbarer Parameter hat einen für jeden der 8 Sätze</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n entries; expected 1 (or 8, one for each set)</source>
        <translation>
            <numerusform>%n Eintrag; erwartet wird 1 (oder 8, einer für jeden Satz)</numerusform>
            <numerusform>%n Einträge; erwartet wird 1 (oder 8, einer für jeden Satz)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1, but plaintextDefinitions has %n entries</source>
        <translation>
            <numerusform>%1, aber plaintextDefinitions hat %n Eintrag</numerusform>
            <numerusform>%1, aber plaintextDefinitions hat %n Einträge</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is not in group %2 (%3)</source>
        <translation>%1 liegt nicht in Gruppe %2 (%3)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not one Latin-1 character</source>
        <translation>„%1“ ist nicht genau ein Latin-1-Zeichen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; appears twice</source>
        <translation>„%1“ kommt doppelt vor</translation>
    </message>
    <message>
        <source>%1 is also the address of group %2</source>
        <translation>%1 ist auch die Adresse von Gruppe %2</translation>
    </message>
    <message>
        <source>%1 appears twice</source>
        <translation>%1 kommt doppelt vor</translation>
    </message>
    <message>
        <source>not valid JSON: %1 at line %2, column %3</source>
        <translation>kein gültiges JSON: %1 in Zeile %2, Spalte %3</translation>
    </message>
    <message>
        <source>not a DriveDesk parameter file: the document is not a JSON object</source>
        <translation>keine DriveDesk-Parameterdatei: das Dokument ist kein JSON-Objekt</translation>
    </message>
    <message>
        <source>not a DriveDesk parameter file: format is %1, expected &apos;%2&apos;</source>
        <translation>keine DriveDesk-Parameterdatei: Format ist %1, erwartet wird „%2“</translation>
    </message>
    <message>
        <source>missing or not a string</source>
        <translation>fehlt oder ist keine Zeichenkette</translation>
    </message>
    <message>
        <source>version: missing or not a number</source>
        <translation>version: fehlt oder ist keine Zahl</translation>
    </message>
    <message>
        <source>version: %1 is not supported (this DriveDesk reads version %2)</source>
        <translation>version: %1 wird nicht unterstützt (dieses DriveDesk liest Version %2)</translation>
    </message>
    <message>
        <source>version: %1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</source>
        <translation>version: %1 ist ein neueres Format, als dieses DriveDesk liest (Version %2); ein neueres DriveDesk liest es</translation>
    </message>
    <message>
        <source>%1 is below min %2</source>
        <translation>%1 liegt unter min %2</translation>
    </message>
    <message>
        <source>%1 is outside min..max (%2..%3), and properties1 says default and limits are constant</source>
        <translation>%1 liegt außerhalb von min..max (%2..%3), und properties1 sagt, dass Vorgabewert und Grenzen fest sind</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot stand in a parameter id: %2</source>
        <translation>„%1“ kann nicht in einer Parameterkennung stehen: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names another address</source>
        <translation>„%1“ bezeichnet eine andere Adresse</translation>
    </message>
    <message>
        <source>%1 (line %2, column %3)</source>
        <translation>%1 (Zeile %2, Spalte %3)</translation>
    </message>
    <message>
        <source>%1: appears twice in one object (line %2, column %3)</source>
        <translation>%1: kommt in einem Objekt zweimal vor (Zeile %2, Spalte %3)</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <comment>a parameter id, then a set or a field of it</comment>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>ParameterFormat</name>
    <message>
        <source>%1 is outside the limits %2 .. %3</source>
        <translation>%1 liegt außerhalb der Grenzwerte %2 .. %3</translation>
    </message>
    <message>
        <source>no value given</source>
        <translation>kein Wert angegeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a whole number</source>
        <translation>„%1“ ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos; does not fit in 32 bits</source>
        <translation>„%1“ passt nicht in 32 Bit</translation>
    </message>
    <message>
        <source>%1 cannot be set exactly: the nearest value this parameter can hold is %2</source>
        <translation>%1 lässt sich nicht genau einstellen: der nächste Wert, den dieser Parameter annehmen kann, ist %2</translation>
    </message>
</context>
<context>
    <name>ParameterId</name>
    <message>
        <source>no parameter given</source>
        <translation>kein Parameter angegeben</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: address above FFFFh</source>
        <translation>„%1“: Adresse über FFFFh</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the group id is ambiguous (&apos;%2&apos; or &apos;%3&apos;); write it with its case</source>
        <translation>„%1“: die Gruppenkennung ist mehrdeutig („%2“ oder „%3“); mit Groß-/Kleinschreibung angeben</translation>
    </message>
    <message>
        <source>no group &apos;%1&apos; on this drive</source>
        <translation>keine Gruppe „%1“ in diesem Umrichter</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: parameter number above 255</source>
        <translation>„%1“: Parameternummer über 255</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: parameter number above %2 in group %3</source>
        <translation>„%1“: Parameternummer über %2 in Gruppe %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a parameter id: write it as group.number (ru.03, ru03) or as a hexadecimal address (0203h, 0x0203)</source>
        <translation>„%1“ ist keine Parameterkennung: als Gruppe.Nummer (ru.03, ru03) oder als hexadezimale Adresse (0203h, 0x0203) angeben</translation>
    </message>
</context>
<context>
    <name>ParameterList</name>
    <message>
        <source>not part of a parameter list</source>
        <translation>nicht Teil einer Parameterliste</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>schreibgeschützt</translation>
    </message>
    <message>
        <source>read-only for parameter lists</source>
        <translation>schreibgeschützt für Parameterlisten</translation>
    </message>
    <message>
        <source>the drive sets this value itself</source>
        <translation>der Umrichter setzt diesen Wert selbst</translation>
    </message>
</context>
<context>
    <name>ParameterProperties</name>
    <message>
        <source>stored as byte</source>
        <translation>gespeichert als Byte</translation>
    </message>
    <message>
        <source>stored as word</source>
        <translation>gespeichert als Wort</translation>
    </message>
    <message>
        <source>stored as long</source>
        <translation>gespeichert als Long</translation>
    </message>
    <message>
        <source>storage width 3 (not used)</source>
        <translation>Speicherbreite 3 (nicht genutzt)</translation>
    </message>
    <message>
        <source>scaling result: byte</source>
        <translation>Normierungsergebnis: Byte</translation>
    </message>
    <message>
        <source>scaling result: word</source>
        <translation>Normierungsergebnis: Wort</translation>
    </message>
    <message>
        <source>scaling result: long</source>
        <translation>Normierungsergebnis: Long</translation>
    </message>
    <message>
        <source>scaling result: none</source>
        <translation>Normierungsergebnis: keines</translation>
    </message>
    <message>
        <source>lower limit variable at power on</source>
        <translation>Untergrenze variabel bei Power On</translation>
    </message>
    <message>
        <source>lower limit always variable</source>
        <translation>Untergrenze immer variabel</translation>
    </message>
    <message>
        <source>lower limit type 3 (not used)</source>
        <translation>Untergrenze Typ 3 (nicht genutzt)</translation>
    </message>
    <message>
        <source>upper limit variable at power on</source>
        <translation>Obergrenze variabel bei Power On</translation>
    </message>
    <message>
        <source>upper limit always variable</source>
        <translation>Obergrenze immer variabel</translation>
    </message>
    <message>
        <source>upper limit type 3 (not used)</source>
        <translation>Obergrenze Typ 3 (nicht genutzt)</translation>
    </message>
    <message>
        <source>no enter</source>
        <translation>kein Enter</translation>
    </message>
    <message>
        <source>enter with dot</source>
        <translation>Enter mit Punkt</translation>
    </message>
    <message>
        <source>enter without dot</source>
        <translation>Enter ohne Punkt</translation>
    </message>
    <message>
        <source>enter mode 3 (not used)</source>
        <translation>Enter-Modus 3 (nicht genutzt)</translation>
    </message>
    <message>
        <source>no display filtering</source>
        <translation>keine Beruhigung</translation>
    </message>
    <message>
        <source>display filtering: time slot</source>
        <translation>Anzeigeberuhigung: Zeitraster</translation>
    </message>
    <message>
        <source>display filtering: filter</source>
        <translation>Anzeigeberuhigung: Filter</translation>
    </message>
    <message>
        <source>display filtering 3 (not used)</source>
        <translation>Anzeigeberuhigung 3 (nicht genutzt)</translation>
    </message>
    <message>
        <source>signed</source>
        <translation>mit Vorzeichen</translation>
    </message>
    <message>
        <source>set-programmable</source>
        <translation>satzprogrammierbar</translation>
    </message>
    <message>
        <source>writable while the active set is displayed</source>
        <translation>schreibbar bei Anzeige des aktuellen Satzes</translation>
    </message>
    <message>
        <source>scaled in the background</source>
        <translation>Normierung im Hintergrund</translation>
    </message>
    <message>
        <source>variable default value</source>
        <translation>Defaultwert variabel</translation>
    </message>
    <message>
        <source>default loaded only for a new device</source>
        <translation>Defaultwert nur bei neuem Gerät laden</translation>
    </message>
    <message>
        <source>not permitted as process data or for surveillance</source>
        <translation>nicht als Prozessdatum oder Überwachungsparameter zugelassen</translation>
    </message>
    <message>
        <source>encoder parameter</source>
        <translation>Encoder-Parameter</translation>
    </message>
    <message>
        <source>system parameter</source>
        <translation>Systemparameter</translation>
    </message>
    <message>
        <source>variable display scaling</source>
        <translation>variable Anzeigenormierung</translation>
    </message>
    <message>
        <source>visible on the display</source>
        <translation>sichtbar auf der Anzeige</translation>
    </message>
    <message>
        <source>writable on the display</source>
        <translation>schreibbar auf der Anzeige</translation>
    </message>
    <message>
        <source>visible in COMBIVIS</source>
        <translation>sichtbar über COMBIVIS</translation>
    </message>
    <message>
        <source>writable via COMBIVIS</source>
        <translation>schreibbar über COMBIVIS</translation>
    </message>
    <message>
        <source>rotating count</source>
        <translation>rotierende Zählweise</translation>
    </message>
    <message>
        <source>changed by the inverter</source>
        <translation>wird vom Umrichter geändert</translation>
    </message>
    <message>
        <source>value without plaintext not displayed</source>
        <translation>Wert ohne Klartext wird nicht angezeigt</translation>
    </message>
    <message>
        <source>configuration flag set (indirect configuration parameters, offline time base µs)</source>
        <translation>Konfigurationsflag gesetzt (indirekt adressierte Konfiguration, Offline-Zeitbasis µs)</translation>
    </message>
    <message>
        <source>write always: written by upload and download</source>
        <translation>Write Always: bei Up- und Download geschrieben</translation>
    </message>
    <message>
        <source>write only: not read by upload, written by download</source>
        <translation>Write Only: beim Upload nicht gelesen, beim Download geschrieben</translation>
    </message>
    <message>
        <source>excluded from the complete parameter list</source>
        <translation>nicht in der kompletten Parameterliste</translation>
    </message>
    <message>
        <source>not permitted as CP parameter</source>
        <translation>nicht als CP-Parameter zugelassen</translation>
    </message>
    <message>
        <source>decimal value of plaintexts suppressed</source>
        <translation>Dezimalwert des Klartextes unterdrückt</translation>
    </message>
    <message>
        <source>read-only for up/download lists: not written by download</source>
        <translation>Read Only für Up-/Download-Listen: beim Download nicht geschrieben</translation>
    </message>
    <message>
        <source>protected</source>
        <translation>geschützt</translation>
    </message>
    <message>
        <source>writable only at nop or error</source>
        <translation>nur schreibbar bei nop oder Fehler</translation>
    </message>
    <message>
        <source>default not loaded while invisible</source>
        <translation>Defaultwert bei Unsichtbarkeit nicht geladen</translation>
    </message>
    <message>
        <source>shows the state at &apos;NOP&apos; and &apos;LS&apos;</source>
        <translation>zeigt bei &apos;NOP&apos; und &apos;LS&apos; den Status</translation>
    </message>
    <message>
        <source>indirectly addressed</source>
        <translation>indirekt adressiert</translation>
    </message>
    <message>
        <source>not set-programmable for &apos;foc synchron&apos;</source>
        <translation>nicht satzprogrammierbar für &apos;foc synchron&apos;</translation>
    </message>
    <message>
        <source>read level: %1</source>
        <translation>Passwortlevel Lesen: %1</translation>
    </message>
    <message>
        <source>write level: %1</source>
        <translation>Passwortlevel Schreiben: %1</translation>
    </message>
    <message numerus="yes">
        <source>visible for inverter type(s) %1</source>
        <translation>
            <numerusform>sichtbar für Umrichtertyp %1</numerusform>
            <numerusform>sichtbar für Umrichtertypen %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>writable for inverter type(s) %1</source>
        <translation>
            <numerusform>schreibbar für Umrichtertyp %1</numerusform>
            <numerusform>schreibbar für Umrichtertypen %1</numerusform>
        </translation>
    </message>
    <message>
        <source>read-only via COMBIVIS</source>
        <translation>über COMBIVIS nur lesbar</translation>
    </message>
    <message>
        <source>properties 2: free bit %1 set</source>
        <translation>Eigenschaften 2: freies Bit %1 gesetzt</translation>
    </message>
</context>
<context>
    <name>ParameterTable</name>
    <message numerus="yes">
        <source>%n group(s)</source>
        <translation>
            <numerusform>%n Gruppe</numerusform>
            <numerusform>%n Gruppen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n Parameter</numerusform>
            <numerusform>%n Parameter</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (sets 0-7)</source>
        <translation>%1 (Sätze 0-7)</translation>
    </message>
    <message>
        <source>parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <source>default</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>connection: %1 (%2)</source>
        <translation>Verbindung: %1 (%2)</translation>
    </message>
    <message>
        <source>group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>set</source>
        <translation>Satz</translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n Unterschied</numerusform>
            <numerusform>%n Unterschiede</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) on both sides</source>
        <translation>
            <numerusform>%n Parameter auf beiden Seiten</numerusform>
            <numerusform>%n Parameter auf beiden Seiten</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PasswordLevel</name>
    <message>
        <source>CP read only</source>
        <translation>CP nur lesen</translation>
    </message>
    <message>
        <source>CP read/write</source>
        <translation>CP lesen/schreiben</translation>
    </message>
    <message>
        <source>CP service</source>
        <translation>CP Service</translation>
    </message>
    <message>
        <source>Application</source>
        <translation>Applikation</translation>
    </message>
    <message>
        <source>Drive mode</source>
        <translation>Drive-Mode</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>nicht genutzt</translation>
    </message>
    <message>
        <source>Security</source>
        <translation>Security</translation>
    </message>
    <message>
        <source>Supervisor</source>
        <translation>Supervisor</translation>
    </message>
</context>
<context>
    <name>Plaintexts</name>
    <message>
        <source>definition %1</source>
        <translation>Definition %1</translation>
    </message>
    <message>
        <source>%1 (no plaintext in %2)</source>
        <translation>%1 (kein Klartext in %2)</translation>
    </message>
    <message>
        <source>%1 (no plaintext)</source>
        <translation>%1 (kein Klartext)</translation>
    </message>
    <message>
        <source>other bits %1</source>
        <translation>weitere Bits %1</translation>
    </message>
    <message>
        <source>this parameter has no plaintexts</source>
        <translation>dieser Parameter hat keine Klartexte</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a plaintext of this parameter; allowed: %2</source>
        <translation>„%1“ ist kein Klartext dieses Parameters; zulässig: %2</translation>
    </message>
    <message>
        <source>no text given; allowed: %1</source>
        <translation>kein Text angegeben; zulässig: %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has an empty text between &apos;|&apos;</source>
        <translation>„%1“ hat einen leeren Text zwischen „|“</translation>
    </message>
    <message>
        <source>&apos;%1&apos; and &apos;%2&apos; are texts of the same definition</source>
        <translation>„%1“ und „%2“ sind Texte derselben Definition</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a text of several definitions: give one text for each definition, in order (%2)</source>
        <translation>„%1“ ist ein Text mehrerer Definitionen: je Definition einen Text angeben, in dieser Reihenfolge (%2)</translation>
    </message>
</context>
<context>
    <name>PlantDrive</name>
    <message>
        <source>found</source>
        <translation>gefunden</translation>
    </message>
    <message>
        <source>saved</source>
        <translation>gesichert</translation>
    </message>
    <message>
        <source>equal</source>
        <translation>gleich</translation>
    </message>
    <message>
        <source>different</source>
        <translation>verschieden</translation>
    </message>
    <message>
        <source>another kind of drive</source>
        <translation>ein anderer Umrichtertyp</translation>
    </message>
    <message>
        <source>no file</source>
        <translation>keine Datei</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>unreachable</source>
        <translation>nicht erreichbar</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>written</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <source>already equal, nothing written</source>
        <translation>schon gleich, nichts geschrieben</translation>
    </message>
    <message>
        <source>dry run</source>
        <translation>Probelauf</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n drive(s) %2</source>
        <translation>
            <numerusform>%1 von %n Umrichter %2</numerusform>
            <numerusform>%1 von %n Umrichtern %2</numerusform>
        </translation>
    </message>
    <message>
        <source>not: %1</source>
        <translation>nicht: %1</translation>
    </message>
</context>
<context>
    <name>PlantFile</name>
    <message>
        <source>an HSP5 link reaches one drive: addresses are for a DIN66019 bus, leave them out</source>
        <translation>eine HSP5-Verbindung erreicht einen Umrichter: Adressen gelten für einen DIN66019-Bus, weglassen</translation>
    </message>
    <message>
        <source>empty: leave addresses out to search the bus for drives</source>
        <translation>leer: addresses weglassen, um den Bus nach Umrichtern zu durchsuchen</translation>
    </message>
    <message>
        <source>drive address %1 appears twice</source>
        <translation>Umrichteradresse %1 kommt zweimal vor</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is also the name of links[%2]: each link needs a name of its own</source>
        <translation>„%1“ ist auch der Name von links[%2]: jede Verbindung braucht einen eigenen Namen</translation>
    </message>
    <message>
        <source>unknown protocol &apos;%1&apos;: use hsp5, din66019ii or din66019</source>
        <translation>unbekanntes Protokoll „%1“: hsp5, din66019ii oder din66019 angeben</translation>
    </message>
    <message>
        <source>%1, expected &apos;%2&apos;: not a DriveDesk plant file</source>
        <translation>%1, erwartet „%2“: keine DriveDesk-Anlagendatei</translation>
    </message>
    <message>
        <source>not a string</source>
        <translation>keine Zeichenkette</translation>
    </message>
    <message>
        <source>%1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</source>
        <translation>%1 ist ein neueres Format, als dieses DriveDesk liest (Version %2); ein neueres DriveDesk liest es</translation>
    </message>
    <message>
        <source>empty: a link needs a name</source>
        <translation>leer: eine Verbindung braucht einen Namen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is longer than %2 characters</source>
        <translation>„%1“ ist länger als %2 Zeichen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; cannot be part of a file name: use letters a-z, digits, &apos;-&apos;, &apos;_&apos; and &apos;.&apos;, starting with a letter or digit</source>
        <translation>„%1“ kann nicht Teil eines Dateinamens sein: Buchstaben a-z, Ziffern, „-“, „_“ und „.“ verwenden, beginnend mit einem Buchstaben oder einer Ziffer</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names a device on Windows: choose another name</source>
        <translation>„%1“ bezeichnet unter Windows ein Gerät: einen anderen Namen wählen</translation>
    </message>
    <message>
        <source>%1 (line %2, column %3)</source>
        <translation>%1 (Zeile %2, Spalte %3)</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <translation>kein gültiges JSON: %1</translation>
    </message>
    <message>
        <source>not a DriveDesk plant file: the document is not a JSON object</source>
        <translation>keine DriveDesk-Anlagendatei: das Dokument ist kein JSON-Objekt</translation>
    </message>
    <message>
        <source>%1: appears twice in one object</source>
        <translation>%1: kommt in einem Objekt zweimal vor</translation>
    </message>
    <message>
        <source>empty: give the machine a name</source>
        <translation>leer: der Maschine einen Namen geben</translation>
    </message>
    <message>
        <source>empty: a plant has at least one link</source>
        <translation>leer: eine Anlage hat mindestens eine Verbindung</translation>
    </message>
</context>
<context>
    <name>Reply</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message numerus="yes">
        <source>drive refused: %1 (after %n attempt(s))</source>
        <translation>
            <numerusform>Umrichter lehnt ab: %1 (nach %n Versuch)</numerusform>
            <numerusform>Umrichter lehnt ab: %1 (nach %n Versuchen)</numerusform>
        </translation>
    </message>
    <message>
        <source>drive refused: %1</source>
        <translation>Umrichter lehnt ab: %1</translation>
    </message>
    <message>
        <source>no valid answer from the drive</source>
        <translation>keine gültige Antwort vom Umrichter</translation>
    </message>
    <message numerus="yes">
        <source>no valid answer from the drive after %n attempt(s)</source>
        <translation>
            <numerusform>keine gültige Antwort vom Umrichter nach %n Versuch</numerusform>
            <numerusform>keine gültige Antwort vom Umrichter nach %n Versuchen</numerusform>
        </translation>
    </message>
    <message>
        <source>the connection to the drive was lost</source>
        <translation>die Verbindung zum Umrichter ist abgebrochen</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>not connected to a drive</source>
        <translation>nicht mit einem Umrichter verbunden</translation>
    </message>
    <message>
        <source>this request cannot be sent</source>
        <translation>diese Anfrage kann nicht gesendet werden</translation>
    </message>
    <message>
        <source>sent to a group of drives or to all drives, which never answer: carried out, not confirmed</source>
        <translation>an eine Gruppe oder an alle Umrichter gesendet, die nie antworten: ausgeführt, nicht bestätigt</translation>
    </message>
    <message>
        <source>the drive stopped answering</source>
        <translation>der Umrichter antwortet nicht mehr</translation>
    </message>
    <message>
        <source>the drive stopped answering: %1</source>
        <translation>der Umrichter antwortet nicht mehr: %1</translation>
    </message>
</context>
<context>
    <name>ReplyCheck</name>
    <message>
        <source>a text with the control character %1h</source>
        <translation>ein Text mit dem Steuerzeichen %1h</translation>
    </message>
    <message>
        <source>limits %1 .. %2: the minimum lies above the maximum</source>
        <translation>Grenzen %1 .. %2: das Minimum liegt über dem Maximum</translation>
    </message>
    <message>
        <source>a display scaling that cannot be computed (%1)</source>
        <translation>eine Anzeigenormierung, die nicht berechnet werden kann (%1)</translation>
    </message>
    <message>
        <source>a group of %1 parameters numbered 0 to %2</source>
        <translation>eine Gruppe von %1 Parametern, nummeriert von 0 bis %2</translation>
    </message>
    <message>
        <source>%1 lies outside the limits %2 .. %3</source>
        <translation>%1 liegt außerhalb der Grenzen %2 .. %3</translation>
    </message>
</context>
<context>
    <name>RunJournal</name>
    <message>
        <source>Drive &gt; Journal Every Write off writes without it</source>
        <translation>Umrichter &gt; Schreibvorgänge im Journal festhalten aus: schreibt ohne Journal</translation>
    </message>
</context>
<context>
    <name>SavedFile</name>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>ScopeChannel</name>
    <message>
        <source>Channel %1</source>
        <translation>Kanal %1</translation>
    </message>
    <message>
        <source>%1 (set %2)</source>
        <translation>%1 (Satz %2)</translation>
    </message>
</context>
<context>
    <name>ScopeCsv</name>
    <message>
        <source>there is no channel %1</source>
        <translation>es gibt keinen Kanal %1</translation>
    </message>
    <message>
        <source>the export was cancelled</source>
        <translation>der Export wurde abgebrochen</translation>
    </message>
    <message>
        <source>cannot write the CSV: %1</source>
        <translation>die CSV kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>ScopeCsvReader</name>
    <message>
        <source>cannot read &apos;%1&apos;: %2</source>
        <translation>&apos;%1&apos; kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a scope CSV export: its first column is not &quot;Time [ms]&quot;</source>
        <translation>&apos;%1&apos; ist kein CSV-Export des Oszilloskops: die erste Spalte ist nicht &quot;Time [ms]&quot;</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2 has %3 fields, the header %4</source>
        <translation>&apos;%1&apos;, Zeile %2 hat %3 Felder, die Kopfzeile %4</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2: &quot;%3&quot; in column &quot;%4&quot; is not a number</source>
        <translation>&apos;%1&apos;, Zeile %2: &quot;%3&quot; in Spalte &quot;%4&quot; ist keine Zahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos;, line %2: the time %3 ms is earlier than the line&apos;s before</source>
        <translation>&apos;%1&apos;, Zeile %2: die Zeit %3 ms liegt vor der der Zeile davor</translation>
    </message>
</context>
<context>
    <name>ScopeFile</name>
    <message>
        <source>cannot read &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is damaged: %2</source>
        <translation>„%1“ ist beschädigt: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a DriveDesk scope file</source>
        <translation>„%1“ ist keine DriveDesk-Scope-Datei</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is in scope file format %2 of a newer DriveDesk; this version reads format %3</source>
        <translation>„%1“ hat das Scope-Dateiformat %2 eines neueren DriveDesk; diese Version liest Format %3</translation>
    </message>
    <message>
        <source>its header cannot be %1 bytes long</source>
        <translation>ihr Kopf kann nicht %1 Byte lang sein</translation>
    </message>
    <message>
        <source>its header is cut short</source>
        <translation>ihr Kopf ist abgeschnitten</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has a damaged header: %2</source>
        <translation>„%1“ hat einen beschädigten Kopf: %2</translation>
    </message>
    <message>
        <source>sample %1 is earlier than the one before it</source>
        <translation>Abtastwert %1 liegt vor dem davor</translation>
    </message>
    <message numerus="yes">
        <source>&apos;%1&apos; ends in an incomplete sample (%n byte(s)), which was left out: the recording was cut off</source>
        <translation>
            <numerusform>„%1“ endet mit einem unvollständigen Abtastwert (%n Byte), der weggelassen wurde: die Aufzeichnung wurde abgeschnitten</numerusform>
            <numerusform>„%1“ endet mit einem unvollständigen Abtastwert (%n Byte), der weggelassen wurde: die Aufzeichnung wurde abgeschnitten</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ScopeFileFormat</name>
    <message>
        <source>not JSON (%1 at byte %2)</source>
        <translation>kein JSON (%1 bei Byte %2)</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>kein JSON-Objekt</translation>
    </message>
    <message>
        <source>expected a date and time (ISO 8601) or null</source>
        <translation>erwartet wurde ein Datum mit Uhrzeit (ISO 8601) oder null</translation>
    </message>
    <message>
        <source>expected %1 channels, found %2</source>
        <translation>erwartet wurden %1 Kanäle, gefunden %2</translation>
    </message>
    <message>
        <source>expected an object</source>
        <translation>erwartet wurde ein Objekt</translation>
    </message>
</context>
<context>
    <name>ScopeFileWriter</name>
    <message>
        <source>cannot write &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>no recording file is open</source>
        <translation>keine Aufzeichnungsdatei ist geöffnet</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: a sample is earlier than the one before it</source>
        <translation>„%1“ kann nicht geschrieben werden: ein Abtastwert liegt vor dem davor</translation>
    </message>
</context>
<context>
    <name>ScopeMathDefinition</name>
    <message>
        <source>a derivative needs samples at two different times</source>
        <translation>eine Ableitung braucht Abtastwerte zu zwei verschiedenen Zeiten</translation>
    </message>
    <message>
        <source>a difference or a sum reads two channels</source>
        <translation>eine Differenz oder Summe liest zwei Kanäle</translation>
    </message>
    <message>
        <source>a derivative, an integral or a moving average reads one channel</source>
        <translation>eine Ableitung, ein Integral oder ein gleitender Mittelwert liest einen Kanal</translation>
    </message>
    <message>
        <source>there is no channel %1 (1..%2)</source>
        <translation>es gibt keinen Kanal %1 (1..%2)</translation>
    </message>
    <message>
        <source>the window is a whole number of samples, at least 1</source>
        <translation>das Fenster ist eine ganze Zahl von Abtastwerten, mindestens 1</translation>
    </message>
    <message>
        <source>the window is a time in ms, more than 0</source>
        <translation>das Fenster ist eine Zeit in ms, größer als 0</translation>
    </message>
    <message>
        <source>unknown kind &quot;%1&quot;</source>
        <translation>unbekannte Art &quot;%1&quot;</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>eine Zahl erwartet</translation>
    </message>
    <message>
        <source>expected samples or ms</source>
        <translation>samples oder ms erwartet</translation>
    </message>
    <message>
        <source>the units differ: %1, %2</source>
        <translation>die Einheiten unterscheiden sich: %1, %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>d/dt %1</source>
        <translation>d/dt %1</translation>
    </message>
    <message>
        <source>∫ %1 dt</source>
        <translation>∫ %1 dt</translation>
    </message>
    <message>
        <source>%1 − %2</source>
        <translation>%1 − %2</translation>
    </message>
    <message>
        <source>%1 + %2</source>
        <translation>%1 + %2</translation>
    </message>
    <message numerus="yes">
        <source>%1, mean of %n sample(s)</source>
        <translation>
            <numerusform>%1, Mittel über %n Abtastwert</numerusform>
            <numerusform>%1, Mittel über %n Abtastwerte</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, mean over %2 ms</source>
        <translation>%1, Mittel über %2 ms</translation>
    </message>
</context>
<context>
    <name>ScopeOverlay</name>
    <message>
        <source>%1 (overlay: %2)</source>
        <comment>a channel&apos;s title, the overlay&apos;s file</comment>
        <translation>%1 (Überlagerung: %2)</translation>
    </message>
    <message>
        <source>the overlay %1 has no trigger (it is no single shot)</source>
        <translation>die Überlagerung %1 hat keinen Trigger (sie ist kein Einzelschuss)</translation>
    </message>
    <message>
        <source>the recording shown has no trigger (it is no single shot)</source>
        <translation>die gezeigte Aufzeichnung hat keinen Trigger (sie ist kein Einzelschuss)</translation>
    </message>
</context>
<context>
    <name>ScopeOverlayTraces</name>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>ScopePollJob</name>
    <message>
        <source>This connection cannot carry scope data (service 18).</source>
        <translation>Diese Verbindung kann keine Scope-Daten übertragen (Dienst 18).</translation>
    </message>
    <message>
        <source>The drive stopped answering: %1</source>
        <translation>Der Umrichter antwortet nicht mehr: %1</translation>
    </message>
</context>
<context>
    <name>ScopePresetFile</name>
    <message>
        <source>expected a number</source>
        <translation>Zahl erwartet</translation>
    </message>
    <message>
        <source>%1 is outside %2..%3</source>
        <translation>%1 liegt außerhalb von %2..%3</translation>
    </message>
    <message>
        <source>%1, expected &apos;%2&apos;: not a DriveDesk scope preset</source>
        <translation>%1, erwartet „%2“: keine DriveDesk-Scope-Vorlage</translation>
    </message>
    <message>
        <source>not a string</source>
        <translation>keine Zeichenkette</translation>
    </message>
    <message>
        <source>%1 is a newer format than this DriveDesk reads (version %2); a newer DriveDesk reads it</source>
        <translation>%1 ist ein neueres Format, als dieses DriveDesk liest (Version %2); ein neueres DriveDesk liest es</translation>
    </message>
    <message>
        <source>expected a parameter id, &quot;off&quot; or null</source>
        <translation>Parameter-ID, „off“ oder null erwartet</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a colour: write it as #rrggbb</source>
        <translation>„%1“ ist keine Farbe: als #rrggbb schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: expected rising or falling</source>
        <translation>„%1“: rising oder falling erwartet</translation>
    </message>
    <message>
        <source>channel %1</source>
        <translation>Kanal %1</translation>
    </message>
    <message>
        <source>channel %1&apos;s %2</source>
        <translation>Kanal %1, %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a parameter id: write it as group.number (ru.03), a hexadecimal address (0203h), with @set where it is read from another set (op.11@2), or off</source>
        <translation>„%1“ ist keine Parameter-ID: als Gruppe.Nummer (ru.03) oder hexadezimale Adresse (0203h) schreiben, mit @Satz, wo aus einem anderen Satz gelesen wird (op.11@2), oder off</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the set after @ is 0..%2, e.g. op.11@2</source>
        <translation>„%1“: der Satz nach @ ist 0..%2, z. B. op.11@2</translation>
    </message>
    <message>
        <source>%1 (line %2, column %3)</source>
        <translation>%1 (Zeile %2, Spalte %3)</translation>
    </message>
    <message>
        <source>not JSON: %1</source>
        <translation>kein JSON: %1</translation>
    </message>
    <message>
        <source>not a DriveDesk scope preset: the document is not a JSON object</source>
        <translation>keine DriveDesk-Scope-Vorlage: das Dokument ist kein JSON-Objekt</translation>
    </message>
    <message>
        <source>%1: appears twice in one object</source>
        <translation>%1: kommt in einem Objekt zweimal vor</translation>
    </message>
    <message>
        <source>give the preset a name of 1 to %1 characters</source>
        <translation>der Vorlage einen Namen mit 1 bis %1 Zeichen geben</translation>
    </message>
    <message>
        <source>expected %1 channels, found %2</source>
        <translation>%1 Kanäle erwartet, %2 gefunden</translation>
    </message>
    <message>
        <source>preset file &apos;%1&apos;: %2</source>
        <translation>Vorlagendatei „%1“: %2</translation>
    </message>
</context>
<context>
    <name>ScopePresetLibrary</name>
    <message>
        <source>cannot make the folder &apos;%1&apos; for the presets</source>
        <translation>der Ordner „%1“ für die Vorlagen lässt sich nicht anlegen</translation>
    </message>
</context>
<context>
    <name>ScopeSpectrum</name>
    <message>
        <source>too few samples for a spectrum: %1 in the window, at least %2 needed</source>
        <translation>zu wenige Abtastwerte für ein Spektrum: %1 im Fenster, mindestens %2 nötig</translation>
    </message>
    <message>
        <source>the samples span no time: all %1 are in one ms</source>
        <translation>die Abtastwerte umfassen keine Zeit: alle %1 liegen in einer ms</translation>
    </message>
    <message>
        <source>not enough memory for a spectrum</source>
        <translation>nicht genug Speicher für ein Spektrum</translation>
    </message>
</context>
<context>
    <name>ScopeSpectrumPlot</name>
    <message>
        <source>Frequency [Hz]</source>
        <translation>Frequenz [Hz]</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <source>Frequency</source>
        <translation>Frequenz</translation>
    </message>
    <message>
        <source>The highest peaks, the highest first</source>
        <translation>Die höchsten Spitzen, die höchste zuerst</translation>
    </message>
    <message>
        <source>Amplitude [%1]</source>
        <translation>Amplitude [%1]</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
</context>
<context>
    <name>ScopeTraces</name>
    <message>
        <source>%1 [%2]</source>
        <comment>channel title and unit</comment>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <source>Value [%1]</source>
        <comment>the units of the channels on the shared axis</comment>
        <translation>Wert [%1]</translation>
    </message>
</context>
<context>
    <name>SetList</name>
    <message>
        <source>no set</source>
        <translation>kein Satz</translation>
    </message>
    <message>
        <source>all sets</source>
        <translation>alle Sätze</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>Satz %1</translation>
    </message>
    <message>
        <source>sets %1</source>
        <translation>Sätze %1</translation>
    </message>
    <message>
        <source>active set</source>
        <translation>aktiver Satz</translation>
    </message>
    <message>
        <source>set of the set pointer</source>
        <translation>Satz des Satzzeigers</translation>
    </message>
    <message>
        <source>set selection %1</source>
        <translation>Satzauswahl %1</translation>
    </message>
</context>
<context>
    <name>Telegram</name>
    <message>
        <source>unspecified</source>
        <translation>nicht festgelegt</translation>
    </message>
    <message>
        <source>status interrogation</source>
        <translation>Statusabfrage</translation>
    </message>
    <message>
        <source>DIN66019 value</source>
        <translation>DIN66019-Wert</translation>
    </message>
    <message>
        <source>value (set mask)</source>
        <translation>Wert (Satzmaske)</translation>
    </message>
    <message>
        <source>value (standard set)</source>
        <translation>Wert (Standardsatz)</translation>
    </message>
    <message>
        <source>limits</source>
        <translation>Grenzen</translation>
    </message>
    <message>
        <source>default value</source>
        <translation>Vorgabewert</translation>
    </message>
    <message>
        <source>properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>display scaling</source>
        <translation>Anzeigenormierung</translation>
    </message>
    <message>
        <source>parameter name</source>
        <translation>Parametername</translation>
    </message>
    <message>
        <source>plaintext indices</source>
        <translation>Klartextindizes</translation>
    </message>
    <message>
        <source>display plaintext</source>
        <translation>Anzeigeklartext</translation>
    </message>
    <message>
        <source>plaintext</source>
        <translation>Klartext</translation>
    </message>
    <message>
        <source>group properties</source>
        <translation>Gruppeneigenschaften</translation>
    </message>
    <message>
        <source>group name</source>
        <translation>Gruppenname</translation>
    </message>
    <message>
        <source>plaintext definition</source>
        <translation>Klartextdefinition</translation>
    </message>
    <message>
        <source>field-bus function</source>
        <translation>Feldbusfunktion</translation>
    </message>
    <message>
        <source>value (subindex)</source>
        <translation>Wert (Subindex)</translation>
    </message>
    <message>
        <source>process data 2x32</source>
        <translation>Prozessdaten 2x32</translation>
    </message>
    <message>
        <source>process data 4x16</source>
        <translation>Prozessdaten 4x16</translation>
    </message>
    <message>
        <source>scope</source>
        <translation>Scope</translation>
    </message>
    <message>
        <source>process data type 4</source>
        <translation>Prozessdaten Typ 4</translation>
    </message>
    <message>
        <source>process data type 5</source>
        <translation>Prozessdaten Typ 5</translation>
    </message>
    <message>
        <source>scope record</source>
        <translation>Scope-Aufzeichnung</translation>
    </message>
    <message>
        <source>default (set mask)</source>
        <translation>Vorgabewert (Satzmaske)</translation>
    </message>
    <message>
        <source>default (standard set)</source>
        <translation>Vorgabewert (Standardsatz)</translation>
    </message>
    <message>
        <source>duplex process data 2x32</source>
        <translation>Duplex-Prozessdaten 2x32</translation>
    </message>
    <message>
        <source>duplex process data 4x16</source>
        <translation>Duplex-Prozessdaten 4x16</translation>
    </message>
    <message>
        <source>duplex process data + parameter</source>
        <translation>Duplex-Prozessdaten + Parameter</translation>
    </message>
    <message>
        <source>duplex process data type 4</source>
        <translation>Duplex-Prozessdaten Typ 4</translation>
    </message>
    <message>
        <source>duplex process data type 5</source>
        <translation>Duplex-Prozessdaten Typ 5</translation>
    </message>
    <message>
        <source>duplex process data type 6</source>
        <translation>Duplex-Prozessdaten Typ 6</translation>
    </message>
    <message>
        <source>service %1</source>
        <translation>Dienst %1</translation>
    </message>
</context>
<context>
    <name>TelegramText</name>
    <message>
        <source> (subindex %1)</source>
        <translation> (Subindex %1)</translation>
    </message>
    <message>
        <source>write %1 = %2%3</source>
        <translation>schreibe %1 = %2%3</translation>
    </message>
    <message>
        <source>read %1%2</source>
        <translation>lies %1%2</translation>
    </message>
    <message>
        <source>reset %1 to its default%2</source>
        <translation>setze %1 auf den Vorgabewert%2</translation>
    </message>
    <message>
        <source>check whether %1 holds its default%2</source>
        <translation>prüfe, ob %1 den Vorgabewert hat%2</translation>
    </message>
    <message>
        <source>read the limits of %1</source>
        <translation>lies die Grenzen von %1</translation>
    </message>
    <message>
        <source>read the default of %1</source>
        <translation>lies den Vorgabewert von %1</translation>
    </message>
    <message>
        <source>read the properties of %1</source>
        <translation>lies die Eigenschaften von %1</translation>
    </message>
    <message>
        <source>read the display scaling of %1</source>
        <translation>lies die Anzeigenormierung von %1</translation>
    </message>
    <message>
        <source>read the name of group %1</source>
        <translation>lies den Namen der Gruppe %1</translation>
    </message>
    <message>
        <source>read the name of %1</source>
        <translation>lies den Namen von %1</translation>
    </message>
    <message>
        <source>read the plaintext indices of %1</source>
        <translation>lies die Klartextindizes von %1</translation>
    </message>
    <message>
        <source>read the properties of group %1</source>
        <translation>lies die Eigenschaften der Gruppe %1</translation>
    </message>
    <message>
        <source>read plaintext %1.%2.%3</source>
        <translation>lies Klartext %1.%2.%3</translation>
    </message>
    <message>
        <source>read plaintext definition %1.%2</source>
        <translation>lies Klartextdefinition %1.%2</translation>
    </message>
    <message>
        <source>read display plaintext %1.%2 for %3</source>
        <translation>lies Anzeigeklartext %1.%2 für %3</translation>
    </message>
    <message>
        <source>write %1</source>
        <translation>schreibe %1</translation>
    </message>
    <message>
        <source>read %1</source>
        <translation>lies %1</translation>
    </message>
    <message>
        <source>write %1: %2</source>
        <translation>schreibe %1: %2</translation>
    </message>
    <message>
        <source>read %1: %2</source>
        <translation>lies %1: %2</translation>
    </message>
    <message>
        <source>written: %1 = %2%3</source>
        <translation>geschrieben: %1 = %2%3</translation>
    </message>
    <message>
        <source>%1: %2%3</source>
        <translation>%1: %2%3</translation>
    </message>
    <message>
        <source>%1 reset to its default%2</source>
        <translation>%1 auf den Vorgabewert gesetzt%2</translation>
    </message>
    <message>
        <source>%1 holds its default%2</source>
        <translation>%1 hat den Vorgabewert%2</translation>
    </message>
    <message>
        <source>limits of %1: %2 .. %3</source>
        <translation>Grenzen von %1: %2 .. %3</translation>
    </message>
    <message>
        <source>default of %1: %2</source>
        <translation>Vorgabewert von %1: %2</translation>
    </message>
    <message>
        <source>properties of %1: %2, %3</source>
        <translation>Eigenschaften von %1: %2, %3</translation>
    </message>
    <message>
        <source>display scaling of %1: divisor %2, multiplier %3, offset %4, flags %5</source>
        <translation>Anzeigenormierung von %1: Divisor %2, Multiplikator %3, Offset %4, Flags %5</translation>
    </message>
    <message>
        <source>name of group %1: &quot;%2&quot;</source>
        <translation>Name der Gruppe %1: „%2“</translation>
    </message>
    <message>
        <source>name of %1: &quot;%2&quot;</source>
        <translation>Name von %1: „%2“</translation>
    </message>
    <message>
        <source>plaintext indices of %1: display %2 (%3), COMBIVIS %4 (%5)</source>
        <translation>Klartextindizes von %1: Anzeige %2 (%3), COMBIVIS %4 (%5)</translation>
    </message>
    <message>
        <source>group %1: id %2, order %3, highest number %4, count %5</source>
        <translation>Gruppe %1: Kennung %2, Reihenfolge %3, höchste Nummer %4, Anzahl %5</translation>
    </message>
    <message>
        <source>plaintext %1.%2.%3: %4 = &quot;%5&quot;</source>
        <translation>Klartext %1.%2.%3: %4 = „%5“</translation>
    </message>
    <message>
        <source>plaintext definition %1.%2: mask %3, count %4, &quot;%5&quot;</source>
        <translation>Klartextdefinition %1.%2: Maske %3, Anzahl %4, „%5“</translation>
    </message>
    <message>
        <source>scope at %1 ms: %2, %3, %4, %5</source>
        <translation>Scope bei %1 ms: %2, %3, %4, %5</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1: erledigt</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>to drive %1: %2</source>
        <translation>an Umrichter %1: %2</translation>
    </message>
    <message>
        <source>answer to no open request: %1</source>
        <translation>Antwort ohne offene Anfrage: %1</translation>
    </message>
    <message>
        <source>answer to no open request: %1, %2</source>
        <translation>Antwort ohne offene Anfrage: %1, %2</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 abgelehnt: %2</translation>
    </message>
</context>
<context>
    <name>TrafficFile</name>
    <message>
        <source>Cannot save the telegrams to %1: %2</source>
        <translation>Die Telegramme können nicht in %1 gespeichert werden: %2</translation>
    </message>
    <message>
        <source>no file name given</source>
        <translation>kein Dateiname angegeben</translation>
    </message>
</context>
<context>
    <name>TrafficFormat</name>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Characters</source>
        <translation>Zeichen</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>→ drive</source>
        <translation>→ Umrichter</translation>
    </message>
    <message>
        <source>← drive</source>
        <translation>← Umrichter</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>inverter request: %1</source>
        <translation>Anfrage des Umrichters: %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>UploadResult</name>
    <message>
        <source>the upload was cancelled; nothing was saved</source>
        <translation>das Hochladen wurde abgebrochen; nichts wurde gesichert</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>the drive could not be read to the end (%1); nothing was saved</source>
        <translation>der Umrichter konnte nicht bis zum Ende gelesen werden (%1); nichts wurde gesichert</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) of the drive could not be read; nothing was saved</source>
        <translation>
            <numerusform>%n Parameter des Umrichters konnte nicht gelesen werden; nichts wurde gesichert</numerusform>
            <numerusform>%n Parameter des Umrichters konnten nicht gelesen werden; nichts wurde gesichert</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message numerus="yes">
        <source>no value read for set(s) %1</source>
        <translation>
            <numerusform>kein Wert für Satz %1 gelesen</numerusform>
            <numerusform>kein Wert für die Sätze %1 gelesen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ValueChangeText</name>
    <message>
        <source>the drive&apos;s answer cannot be its value: %1</source>
        <translation>die Antwort des Umrichters kann nicht sein Wert sein: %1</translation>
    </message>
</context>
<context>
    <name>WholeFile</name>
    <message>
        <source>cannot read &apos;%1&apos;: %2</source>
        <translation>„%1“ kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is too large (%2 bytes, at most %3)</source>
        <translation>„%1“ ist zu groß (%2 Bytes, höchstens %3)</translation>
    </message>
    <message>
        <source>cannot read &apos;%1&apos;: it is a folder, not a file</source>
        <translation>„%1“ kann nicht gelesen werden: es ist ein Ordner, keine Datei</translation>
    </message>
    <message>
        <source>cannot read &apos;%1&apos;: it is not a regular file but a device or a pipe, whose reading may never end</source>
        <translation>„%1“ kann nicht gelesen werden: es ist keine gewöhnliche Datei, sondern ein Gerät oder eine Pipe, deren Lesen nie enden muss</translation>
    </message>
</context>
</TS>
