<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis hasScaleBasedVisibilityFlag="0" simplifyAlgorithm="0" simplifyLocal="1" simplifyMaxScale="1" minScale="100000000" labelsEnabled="0" symbologyReferenceScale="-1" version="3.22.16-Białowieża" simplifyDrawingTol="1" maxScale="0" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" simplifyDrawingHints="1">
  <renderer-v2 attr="polarity" enableorderby="0" forceraster="0" referencescale="-1" type="categorizedSymbol" symbollevels="0">
    <categories>
      <category symbol="0" value="hot" label="Warm by day" render="true"/>
      <category symbol="1" value="cold" label="Cool by day" render="true"/>
    </categories>
    <symbols>
      <symbol alpha="1" clip_to_extent="1" type="fill" name="0" force_rhr="0">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" enabled="1" class="SimpleFill">
          <Option type="Map">
            <Option value="3x:0,0,0,0,0,0" type="QString" name="border_width_map_unit_scale"/>
            <Option value="0,0,0,0" type="QString" name="color"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="215,48,39,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.5" type="QString" name="outline_width"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="no" type="QString" name="style"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="215,48,39,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol alpha="1" clip_to_extent="1" type="fill" name="1" force_rhr="0">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" enabled="1" class="SimpleFill">
          <Option type="Map">
            <Option value="3x:0,0,0,0,0,0" type="QString" name="border_width_map_unit_scale"/>
            <Option value="0,0,0,0" type="QString" name="color"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="69,117,180,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.5" type="QString" name="outline_width"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="no" type="QString" name="style"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="69,117,180,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <rotation/>
    <sizescale/>
  </renderer-v2>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field configurationFlags="None" name="anomaly_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="x">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="y">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lat">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="7" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lon">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="7" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="area_m2">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diameter_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="circularity">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_sigma_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_sigma_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="status">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="polarity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="class_cue">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="n_scans">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_day_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_night_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="fix_quality">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="figure">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_series">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="p_mine">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="priority">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="set_aside_reason">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="short_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="likelihood">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence_pct">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias index="0" field="anomaly_id" name="Suspect id"/>
    <alias index="1" field="x" name="Easting (m, survey UTM)"/>
    <alias index="2" field="y" name="Northing (m, survey UTM)"/>
    <alias index="3" field="lat" name="Latitude (°, WGS84)"/>
    <alias index="4" field="lon" name="Longitude (°, WGS84)"/>
    <alias index="5" field="area_m2" name="Area (m²)"/>
    <alias index="6" field="diameter_m" name="Diameter (m)"/>
    <alias index="7" field="circularity" name="Circularity (0-1)"/>
    <alias index="8" field="depth_m" name="Burial depth (m)"/>
    <alias index="9" field="depth_sigma_m" name="Depth uncertainty, 1σ (m)"/>
    <alias index="10" field="diffusivity_m2s" name="Thermal diffusivity (m²/s)"/>
    <alias index="11" field="diffusivity_sigma_m2s" name="Diffusivity uncertainty, 1σ (m²/s)"/>
    <alias index="12" field="status" name="Characterisation status"/>
    <alias index="13" field="polarity" name="Polarity"/>
    <alias index="14" field="class_cue" name="Class cue"/>
    <alias index="15" field="confidence" name="Class cue confidence (0-1)"/>
    <alias index="16" field="n_scans" name="Scans seen"/>
    <alias index="17" field="contrast_day_k" name="Day contrast (K)"/>
    <alias index="18" field="contrast_night_k" name="Night contrast (K)"/>
    <alias index="19" field="fix_quality" name="GNSS fix quality"/>
    <alias index="20" field="figure" name="Contrast curve"/>
    <alias index="21" field="contrast_series" name="Contrast series (JSON)"/>
    <alias index="22" field="p_mine" name="Mine likelihood (0-1)"/>
    <alias index="23" field="priority" name="Priority (1 = first)"/>
    <alias index="24" field="cue_confidence" name="Class cue confidence (0-1)"/>
    <alias index="25" field="set_aside_reason" name="Set aside because"/>
    <alias index="26" field="short_id" name="Short id"/>
    <alias index="27" field="depth" name="Burial depth ± 1σ"/>
    <alias index="28" field="diffusivity" name="Thermal diffusivity ± 1σ"/>
    <alias index="29" field="likelihood" name="Mine likelihood"/>
    <alias index="30" field="cue_confidence_pct" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default field="anomaly_id" expression="" applyOnUpdate="0"/>
    <default field="x" expression="" applyOnUpdate="0"/>
    <default field="y" expression="" applyOnUpdate="0"/>
    <default field="lat" expression="" applyOnUpdate="0"/>
    <default field="lon" expression="" applyOnUpdate="0"/>
    <default field="area_m2" expression="" applyOnUpdate="0"/>
    <default field="diameter_m" expression="" applyOnUpdate="0"/>
    <default field="circularity" expression="" applyOnUpdate="0"/>
    <default field="depth_m" expression="" applyOnUpdate="0"/>
    <default field="depth_sigma_m" expression="" applyOnUpdate="0"/>
    <default field="diffusivity_m2s" expression="" applyOnUpdate="0"/>
    <default field="diffusivity_sigma_m2s" expression="" applyOnUpdate="0"/>
    <default field="status" expression="" applyOnUpdate="0"/>
    <default field="polarity" expression="" applyOnUpdate="0"/>
    <default field="class_cue" expression="" applyOnUpdate="0"/>
    <default field="confidence" expression="" applyOnUpdate="0"/>
    <default field="n_scans" expression="" applyOnUpdate="0"/>
    <default field="contrast_day_k" expression="" applyOnUpdate="0"/>
    <default field="contrast_night_k" expression="" applyOnUpdate="0"/>
    <default field="fix_quality" expression="" applyOnUpdate="0"/>
    <default field="figure" expression="" applyOnUpdate="0"/>
    <default field="contrast_series" expression="" applyOnUpdate="0"/>
    <default field="p_mine" expression="" applyOnUpdate="0"/>
    <default field="priority" expression="" applyOnUpdate="0"/>
    <default field="cue_confidence" expression="" applyOnUpdate="0"/>
    <default field="set_aside_reason" expression="" applyOnUpdate="0"/>
    <default field="short_id" expression="" applyOnUpdate="0"/>
    <default field="depth" expression="" applyOnUpdate="0"/>
    <default field="diffusivity" expression="" applyOnUpdate="0"/>
    <default field="likelihood" expression="" applyOnUpdate="0"/>
    <default field="cue_confidence_pct" expression="" applyOnUpdate="0"/>
  </defaults>
  <constraints>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="anomaly_id"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="x"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="y"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="lat"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="lon"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="area_m2"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="diameter_m"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="circularity"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="depth_m"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="depth_sigma_m"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="diffusivity_m2s"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="diffusivity_sigma_m2s"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="status"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="polarity"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="class_cue"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="confidence"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="n_scans"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="contrast_day_k"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="contrast_night_k"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="fix_quality"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="figure"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="contrast_series"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="p_mine"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="priority"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="cue_confidence"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="set_aside_reason"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="short_id"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="depth"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="diffusivity"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="likelihood"/>
    <constraint constraints="0" unique_strength="0" notnull_strength="0" exp_strength="0" field="cue_confidence_pct"/>
  </constraints>
  <constraintExpressions>
    <constraint desc="" field="anomaly_id" exp=""/>
    <constraint desc="" field="x" exp=""/>
    <constraint desc="" field="y" exp=""/>
    <constraint desc="" field="lat" exp=""/>
    <constraint desc="" field="lon" exp=""/>
    <constraint desc="" field="area_m2" exp=""/>
    <constraint desc="" field="diameter_m" exp=""/>
    <constraint desc="" field="circularity" exp=""/>
    <constraint desc="" field="depth_m" exp=""/>
    <constraint desc="" field="depth_sigma_m" exp=""/>
    <constraint desc="" field="diffusivity_m2s" exp=""/>
    <constraint desc="" field="diffusivity_sigma_m2s" exp=""/>
    <constraint desc="" field="status" exp=""/>
    <constraint desc="" field="polarity" exp=""/>
    <constraint desc="" field="class_cue" exp=""/>
    <constraint desc="" field="confidence" exp=""/>
    <constraint desc="" field="n_scans" exp=""/>
    <constraint desc="" field="contrast_day_k" exp=""/>
    <constraint desc="" field="contrast_night_k" exp=""/>
    <constraint desc="" field="fix_quality" exp=""/>
    <constraint desc="" field="figure" exp=""/>
    <constraint desc="" field="contrast_series" exp=""/>
    <constraint desc="" field="p_mine" exp=""/>
    <constraint desc="" field="priority" exp=""/>
    <constraint desc="" field="cue_confidence" exp=""/>
    <constraint desc="" field="set_aside_reason" exp=""/>
    <constraint desc="" field="short_id" exp=""/>
    <constraint desc="" field="depth" exp=""/>
    <constraint desc="" field="diffusivity" exp=""/>
    <constraint desc="" field="likelihood" exp=""/>
    <constraint desc="" field="cue_confidence_pct" exp=""/>
  </constraintExpressions>
  <expressionfields>
    <field typeName="" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" subType="0" name="short_id" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" subType="0" name="depth" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" subType="0" name="diffusivity" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" subType="0" name="likelihood" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" subType="0" name="cue_confidence_pct" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" subType="0" name="short_id" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" subType="0" name="depth" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" subType="0" name="diffusivity" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" subType="0" name="likelihood" length="0" type="10" precision="0" comment=""/>
    <field typeName="" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" subType="0" name="cue_confidence_pct" length="0" type="10" precision="0" comment=""/>
  </expressionfields>
  <attributetableconfig actionWidgetStyle="dropDown" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" sortOrder="0">
    <columns>
      <column width="-1" hidden="0" type="field" name="anomaly_id"/>
      <column width="-1" hidden="0" type="field" name="polarity"/>
      <column width="-1" hidden="0" type="field" name="area_m2"/>
      <column width="-1" hidden="0" type="field" name="p_mine"/>
      <column width="-1" hidden="0" type="field" name="priority"/>
      <column width="-1" hidden="0" type="field" name="cue_confidence"/>
      <column width="-1" hidden="0" type="field" name="set_aside_reason"/>
      <column width="-1" hidden="0" type="field" name="short_id"/>
      <column width="-1" hidden="0" type="field" name="depth"/>
      <column width="-1" hidden="0" type="field" name="diffusivity"/>
      <column width="-1" hidden="0" type="field" name="likelihood"/>
      <column width="-1" hidden="0" type="field" name="cue_confidence_pct"/>
      <column width="-1" hidden="1" type="actions"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Suspect" groupBox="0" columnCount="1" visibilityExpression="">
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Identification" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="26" name="short_id"/>
        <attributeEditorField showLabel="1" index="0" name="anomaly_id"/>
        <attributeEditorField showLabel="1" index="23" name="priority"/>
        <attributeEditorField showLabel="1" index="14" name="class_cue"/>
        <attributeEditorField showLabel="1" index="29" name="likelihood"/>
        <attributeEditorField showLabel="1" index="30" name="cue_confidence_pct"/>
        <attributeEditorField showLabel="1" index="12" name="status"/>
        <attributeEditorField showLabel="1" index="13" name="polarity"/>
        <attributeEditorField showLabel="1" index="25" name="set_aside_reason"/>
      </attributeEditorContainer>
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Burial depth and soil" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="27" name="depth"/>
        <attributeEditorField showLabel="1" index="28" name="diffusivity"/>
      </attributeEditorContainer>
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Thermal contrast" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="17" name="contrast_day_k"/>
        <attributeEditorField showLabel="1" index="18" name="contrast_night_k"/>
        <attributeEditorField showLabel="1" index="16" name="n_scans"/>
      </attributeEditorContainer>
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Shape" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="6" name="diameter_m"/>
        <attributeEditorField showLabel="1" index="5" name="area_m2"/>
        <attributeEditorField showLabel="1" index="7" name="circularity"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Contrast curve" groupBox="0" columnCount="1" visibilityExpression="">
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Contrast curve" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="20" name="figure"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Position" groupBox="0" columnCount="1" visibilityExpression="">
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Position" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="1" name="x"/>
        <attributeEditorField showLabel="1" index="2" name="y"/>
        <attributeEditorField showLabel="1" index="3" name="lat"/>
        <attributeEditorField showLabel="1" index="4" name="lon"/>
        <attributeEditorField showLabel="1" index="19" name="fix_quality"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Stored values" groupBox="0" columnCount="1" visibilityExpression="">
      <attributeEditorContainer showLabel="1" visibilityExpressionEnabled="0" name="Stored values" groupBox="1" columnCount="1" visibilityExpression="">
        <attributeEditorField showLabel="1" index="8" name="depth_m"/>
        <attributeEditorField showLabel="1" index="9" name="depth_sigma_m"/>
        <attributeEditorField showLabel="1" index="10" name="diffusivity_m2s"/>
        <attributeEditorField showLabel="1" index="11" name="diffusivity_sigma_m2s"/>
        <attributeEditorField showLabel="1" index="22" name="p_mine"/>
        <attributeEditorField showLabel="1" index="24" name="cue_confidence"/>
        <attributeEditorField showLabel="1" index="15" name="confidence"/>
        <attributeEditorField showLabel="1" index="21" name="contrast_series"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>2</layerGeometryType>
</qgis>
